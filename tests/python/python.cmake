# SPDX-License-Identifier: Apache-2.0
# The Python module's tests (label python): each pytest file a ctest test,
# run by the interpreter the module was built for, against independent NumPy,
# SciPy and scikit-image computations; the module installed into a prefix and
# imported from there; the example notebook run headless.
set(PYTESTS ${CMAKE_CURRENT_SOURCE_DIR}/python)
# The example writes here; each pytest run's --basetemp lies beside it (pytest
# makes that folder without parents, and this one exists).
set(PYOUT ${CMAKE_CURRENT_BINARY_DIR}/python)
set(PYENV "PYTHONPATH=${CMAKE_BINARY_DIR}/python" "CMFILTER_SOURCE_DIR=${PROJECT_SOURCE_DIR}"
          "CMFILTER_CLI=$<TARGET_FILE:cmfilter_cli>" "OCIO=" "PYTHONDONTWRITEBYTECODE=1" "MPLBACKEND=Agg")
# A sanitized module is loaded by an interpreter that is not: AddressSanitizer's
# runtime (which holds UndefinedBehaviorSanitizer's too) must be loaded first,
# and the interpreter's own allocations are not the library's leaks.
if("address" IN_LIST CMFILTER_SANITIZE)
  execute_process(COMMAND ${CMAKE_CXX_COMPILER} -print-file-name=libclang_rt.asan-x86_64.so
                  OUTPUT_VARIABLE asan_runtime OUTPUT_STRIP_TRAILING_WHITESPACE)
  if(NOT EXISTS "${asan_runtime}")
    message(FATAL_ERROR "the Python tests need AddressSanitizer's shared runtime; "
                        "${CMAKE_CXX_COMPILER} -print-file-name=libclang_rt.asan-x86_64.so gave '${asan_runtime}'")
  endif()
  list(APPEND PYENV "LD_PRELOAD=${asan_runtime}"
       "ASAN_OPTIONS=detect_leaks=0:new_delete_type_mismatch=0:check_initialization_order=1")
elseif(CMFILTER_SANITIZE)
  message(STATUS "cmfilter: the Python tests are not registered under CMFILTER_SANITIZE=${CMFILTER_SANITIZE}")
  return()
endif()

file(GLOB test_files CONFIGURE_DEPENDS ${PYTESTS}/test_*.py)
foreach(file ${test_files})
  get_filename_component(name ${file} NAME_WE)
  string(REGEX REPLACE "^test_" "" name ${name})
  add_test(NAME python.${name}
           COMMAND ${Python3_EXECUTABLE} -m pytest -q -p no:cacheprovider --basetemp=${CMAKE_CURRENT_BINARY_DIR}/python-${name} -o
                   console_output_style=classic ${file})
  set_tests_properties(python.${name} PROPERTIES LABELS python ENVIRONMENT "${PYENV}")
endforeach()

# The module installed with the library into package.install's prefix,
# imported from there alone.
add_test(NAME python.installed
         COMMAND ${Python3_EXECUTABLE} ${PYTESTS}/check_installed_module.py ${CMAKE_BINARY_DIR}/tests/package/prefix
                 ${CMFILTER_PYTHON_INSTALL_DIR})
set(installed_env ${PYENV})
list(FILTER installed_env EXCLUDE REGEX "^PYTHONPATH=")
set_tests_properties(python.installed PROPERTIES LABELS "python;package" ENVIRONMENT "${installed_env}"
                     FIXTURES_REQUIRED package_prefix)

# examples/python: bakes a table and plots T(v, sigma) with matplotlib.
add_test(NAME python.example.table_plot
         COMMAND ${Python3_EXECUTABLE} ${PROJECT_SOURCE_DIR}/examples/python/table_plot.py
                 ${PROJECT_SOURCE_DIR}/luts/terrain.png ${PYOUT}/example)
set_tests_properties(python.example.table_plot PROPERTIES LABELS "python;example" ENVIRONMENT "${PYENV}")
