# SPDX-License-Identifier: MIT
# cmake -DTRIBEX=... -DREFERENCE=docs/deck_reference.md -P keys_reference.cmake: the committed deck
# reference must be what `tribex keys --markdown` prints from the schema today.
execute_process(COMMAND ${TRIBEX} keys --markdown RESULT_VARIABLE _rc OUTPUT_VARIABLE _out ERROR_VARIABLE _err)
if(NOT _rc EQUAL 0)
  message(FATAL_ERROR "tribex keys --markdown exited ${_rc}: ${_err}")
endif()
file(READ ${REFERENCE} _ref)
if(NOT _out STREQUAL _ref)
  message(FATAL_ERROR "${REFERENCE} differs from the schema; regenerate it: build/bin/tribex keys --markdown > docs/deck_reference.md")
endif()
