# SPDX-License-Identifier: MIT
# PT-Scotch, the distributed graph partitioner of `begin decomposition` / `method = ptscotch`
# (solver/parallel/ptscotch_partition.cpp). Debian's libptscotch-dev ships neither a CMake config nor
# a pkg-config file: ptscotch.h (which includes scotch.h, package libscotch-dev) in /usr/include/scotch,
# libptscotch.so and its error handler libptscotcherr.so in the library folder. The default flavour,
# /usr/include/scotch with the libraries beside it, has a 32-bit SCOTCH_Num (the int32 flavour); the
# int64 and long flavours live in scotch-int64/ and scotch-long/ and are not used.
find_path(PTSCOTCH_INCLUDE_DIR ptscotch.h PATH_SUFFIXES scotch)
find_library(PTSCOTCH_LIBRARY ptscotch)
find_library(PTSCOTCH_ERR_LIBRARY ptscotcherr)
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(PTScotchLocal
  REQUIRED_VARS PTSCOTCH_LIBRARY PTSCOTCH_ERR_LIBRARY PTSCOTCH_INCLUDE_DIR
  FAIL_MESSAGE "PT-Scotch not found (ptscotch.h, libptscotch.so, libptscotcherr.so): apt-get install libptscotch-dev (./tribex.sh build installs it, docs/dependencies.md)")
if(PTScotchLocal_FOUND AND NOT TARGET PTScotch::PTScotch)
  add_library(PTScotch::PTScotch UNKNOWN IMPORTED)
  set_target_properties(PTScotch::PTScotch PROPERTIES IMPORTED_LOCATION "${PTSCOTCH_LIBRARY}"
                        INTERFACE_INCLUDE_DIRECTORIES "${PTSCOTCH_INCLUDE_DIR}"
                        INTERFACE_LINK_LIBRARIES "${PTSCOTCH_ERR_LIBRARY};MPI::MPI_C")
endif()
