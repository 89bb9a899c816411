# SPDX-License-Identifier: Apache-2.0
# Checks that the committed colour maps in luts/ are exactly what
# cmfilter-make-luts produces today. Run with cmake -P and the variables
# GENERATOR (the cmfilter-make-luts executable), IDIFF (OpenImageIO's idiff),
# COMMITTED_DIR (luts/ in the source tree) and REGENERATED_DIR (a scratch
# folder in the build tree, emptied first). Fails when the generator fails,
# when a regenerated map has no committed counterpart or vice versa, or when
# idiff finds any pixel that differs (thresholds 0: any difference fails).
cmake_minimum_required(VERSION 3.18)

foreach(var GENERATOR IDIFF COMMITTED_DIR REGENERATED_DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "check_luts_regenerate.cmake: ${var} is not set")
  endif()
endforeach()

file(REMOVE_RECURSE "${REGENERATED_DIR}")
file(MAKE_DIRECTORY "${REGENERATED_DIR}")
execute_process(COMMAND "${GENERATOR}" "${REGENERATED_DIR}" RESULT_VARIABLE generator_result)
if(NOT generator_result EQUAL 0)
  message(FATAL_ERROR "cmfilter-make-luts failed (${generator_result})")
endif()

file(GLOB regenerated_maps RELATIVE "${REGENERATED_DIR}" "${REGENERATED_DIR}/*.png")
file(GLOB committed_maps RELATIVE "${COMMITTED_DIR}" "${COMMITTED_DIR}/*.png")
if(NOT regenerated_maps)
  message(FATAL_ERROR "cmfilter-make-luts wrote no maps into ${REGENERATED_DIR}")
endif()

set(failures "")
foreach(map IN LISTS committed_maps)
  if(NOT map IN_LIST regenerated_maps)
    list(APPEND failures "${map}: committed but no longer generated")
  endif()
endforeach()
foreach(map IN LISTS regenerated_maps)
  if(NOT EXISTS "${COMMITTED_DIR}/${map}")
    list(APPEND failures "${map}: generated but missing from ${COMMITTED_DIR}")
    continue()
  endif()
  execute_process(COMMAND "${IDIFF}" -fail 0 -warn 0 "${COMMITTED_DIR}/${map}" "${REGENERATED_DIR}/${map}"
                  RESULT_VARIABLE idiff_result OUTPUT_VARIABLE idiff_output ERROR_VARIABLE idiff_output)
  if(idiff_result EQUAL 0)
    message(STATUS "${map}: identical")
  else()
    list(APPEND failures "${map}: differs from the regenerated map (idiff exit ${idiff_result}):\n${idiff_output}")
  endif()
endforeach()

if(failures)
  list(JOIN failures "\n" report)
  message(FATAL_ERROR "committed colour maps are out of date; regenerate them with "
                      "'build/luts/cmfilter-make-luts luts/':\n${report}")
endif()
