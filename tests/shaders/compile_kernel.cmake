# SPDX-License-Identifier: Apache-2.0
# glslangValidator compiles KERNEL (with its #include libraries from
# INCLUDE_DIR) to OpenGL SPIR-V (-G) and Vulkan SPIR-V (-V), into OUT.*.spv.
foreach(target G V)
  execute_process(COMMAND ${GLSLANG} -${target} -I${INCLUDE_DIR} ${KERNEL} -o ${OUT}.${target}.spv
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "glslangValidator -${target} failed on ${KERNEL}:\n${out}${err}")
  endif()
endforeach()
