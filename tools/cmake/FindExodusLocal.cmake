# SPDX-License-Identifier: MIT
# Debian's libexodusii-dev ships no CMake config: exodusII.h (which includes netcdf.h from
# libnetcdf-dev) and libexoIIv2c. Debian links libexoIIv2c against libnetcdf_mpi, i.e. the Open MPI
# HDF5 that tribex uses too, so the tribex binary has one HDF5 (docs/dependencies.md section 2;
# CTest output_one_hdf5 checks it). Do not add netCDF's own -lnetcdf: that is the serial flavour,
# linked against the serial HDF5.
find_path(EXODUS_INCLUDE_DIR exodusII.h)
find_path(EXODUS_NETCDF_INCLUDE_DIR netcdf.h)
find_library(EXODUS_LIBRARY exoIIv2c)
# The same libnetcdf_mpi, named for mesh/exodus_shapes.cpp's own nc_* calls (the netCDF-4 header checks).
# Debian ships it without a development link (libnetcdf-mpi-19 only), hence the versioned name.
find_library(EXODUS_NETCDF_MPI_LIBRARY NAMES netcdf_mpi libnetcdf_mpi.so.19)
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(ExodusLocal REQUIRED_VARS EXODUS_LIBRARY EXODUS_NETCDF_MPI_LIBRARY EXODUS_INCLUDE_DIR EXODUS_NETCDF_INCLUDE_DIR)
if(ExodusLocal_FOUND AND NOT TARGET Exodus::Exodus)
  add_library(Exodus::Exodus UNKNOWN IMPORTED)
  set_target_properties(Exodus::Exodus PROPERTIES IMPORTED_LOCATION "${EXODUS_LIBRARY}"
                        INTERFACE_INCLUDE_DIRECTORIES "${EXODUS_INCLUDE_DIR};${EXODUS_NETCDF_INCLUDE_DIR}"
                        INTERFACE_LINK_LIBRARIES "${EXODUS_NETCDF_MPI_LIBRARY}")
endif()
