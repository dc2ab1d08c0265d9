# SPDX-License-Identifier: MIT
# Debian's libmetis-dev ships neither a CMake config nor a pkg-config file. Named *Local so that
# CGAL's own FindMETIS (which it appends to CMAKE_MODULE_PATH) does not shadow it.
find_path(METIS_INCLUDE_DIR metis.h PATH_SUFFIXES metis)
find_library(METIS_LIBRARY metis)
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(METISLocal REQUIRED_VARS METIS_LIBRARY METIS_INCLUDE_DIR)
if(METISLocal_FOUND AND NOT TARGET METIS::METIS)
  add_library(METIS::METIS UNKNOWN IMPORTED)
  set_target_properties(METIS::METIS PROPERTIES IMPORTED_LOCATION "${METIS_LIBRARY}"
                        INTERFACE_INCLUDE_DIRECTORIES "${METIS_INCLUDE_DIR}")
endif()
