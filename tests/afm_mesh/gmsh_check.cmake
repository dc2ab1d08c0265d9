# SPDX-License-Identifier: MIT
# cmake -DTRIBEX=... -DGMSH=... -DMAP=... -DOUT=... -P gmsh_check.cmake
# A `tribex mesh afm` mesh with overlapping side sets (substrate_track inside substrate_top,
# substrate_xmin inside substrate_sides) passes `gmsh -check`: no duplicate elements or nodes, no error.
execute_process(COMMAND ${TRIBEX} mesh afm ${MAP} --channel 0 --window 187.5nm,187.5nm,20nm,20nm
                        --track 190nm,190nm,10nm,10nm --element-size 1nm --depth 20nm -o ${OUT}
                RESULT_VARIABLE _rc OUTPUT_VARIABLE _out ERROR_VARIABLE _err)
if(NOT _rc EQUAL 0)
  message(FATAL_ERROR "tribex mesh afm failed (${_rc}):\n${_out}\n${_err}")
endif()
execute_process(COMMAND ${GMSH} ${OUT} -check RESULT_VARIABLE _rc OUTPUT_VARIABLE _out ERROR_VARIABLE _err)
set(_all "${_out}\n${_err}")
if(NOT _rc EQUAL 0 OR _all MATCHES "Error|[0-9]+ duplicate|already exists")
  message(FATAL_ERROR "gmsh -check is not clean (exit ${_rc}):\n${_all}")
endif()
string(REGEX MATCH "Info *: [0-9]+ elements" _count "${_all}")
if(NOT _count)
  message(FATAL_ERROR "gmsh -check did not read the mesh:\n${_all}")
endif()
message(STATUS "gmsh -check clean: ${_count}")
