# SPDX-License-Identifier: Apache-2.0
# Faults: outputs appear whole or not at all (AtomicOutput,
# docs/reliability.md#faults) when a writer is killed (SIGKILL at a spread of
# moments: a table bake, a moment bake, a render), when the disk fills up
# (ulimit -f), when an output cannot be written or an input is cut short,
# and when two writers write the same output at once. `ctest -L faults`.
set(FAULTS ${CMAKE_CURRENT_SOURCE_DIR})
foreach(kind table moments render)
  add_test(NAME cli.faults.kill-${kind}
           COMMAND bash ${FAULTS}/fault_kill.sh ${CMF} ${PROJECT_SOURCE_DIR} ${OUT}/faults-kill-${kind} ${kind})
endforeach()
add_test(NAME cli.faults.full-disk
         COMMAND bash ${FAULTS}/fault_full_disk.sh ${CMF} ${PROJECT_SOURCE_DIR} ${OUT}/faults-full-disk)
add_test(NAME cli.faults.bad-paths
         COMMAND bash ${FAULTS}/fault_bad_paths.sh ${CMF} ${PROJECT_SOURCE_DIR} ${OUT}/faults-bad-paths)
add_test(NAME cli.faults.concurrent-writers
         COMMAND bash ${FAULTS}/fault_concurrent.sh ${CMF} ${PROJECT_SOURCE_DIR} ${OUT}/faults-concurrent)
set_tests_properties(cli.faults.kill-table cli.faults.kill-moments cli.faults.kill-render cli.faults.full-disk
                     cli.faults.bad-paths cli.faults.concurrent-writers
                     PROPERTIES LABELS "cli;faults" FIXTURES_REQUIRED cli_dirs ENVIRONMENT "OCIO=" TIMEOUT 300)
# Under a sanitizer each run is several times slower: fewer kills a series,
# fewer rounds of two writers.
if(CMFILTER_SANITIZE)
  set_property(TEST cli.faults.kill-table cli.faults.kill-moments cli.faults.kill-render
               APPEND PROPERTY ENVIRONMENT "CMFILTER_FAULT_KILLS=4")
  set_property(TEST cli.faults.concurrent-writers APPEND PROPERTY ENVIRONMENT "CMFILTER_FAULT_ROUNDS=2")
  set_property(TEST cli.faults.kill-table cli.faults.kill-moments cli.faults.kill-render
               cli.faults.concurrent-writers APPEND PROPERTY ENVIRONMENT "CMFILTER_FAULT_SMALL=1")
endif()
