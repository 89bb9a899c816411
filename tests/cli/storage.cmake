# SPDX-License-Identifier: Apache-2.0
# -d, --tile and --compression (maketx's spellings) on bake-colormap,
# bake-moments and bake-noise (docs/storage.md).
add_test(NAME cli.storage
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/check_storage.sh ${CMF} ${LUTS}/stripes.png ${FIX}/driver-37x23.png
                 ${OUT}/storage)
set_tests_properties(cli.storage PROPERTIES FIXTURES_REQUIRED "cli_dirs;cli_fixtures" LABELS cli ENVIRONMENT "OCIO=")
set(SO ${OUT}/storage-bad.exr)
cmfilter_cli_case(NAME storage.bad.pixel-type EXIT 3 STDERR "-d 'double' is unknown \\(expected half or float\\)"
                  ABSENT ${SO} COMMAND ${CMF} bake-colormap ${LUTS}/terrain.png -d double -o ${SO})
cmfilter_cli_case(NAME storage.bad.compression EXIT 3
                  STDERR "--compression 'lzw' is unknown \\(expected one of OpenEXR's: none, rle, zips, zip, piz"
                  ABSENT ${SO} COMMAND ${CMF} bake-moments ${FIX}/driver-37x23.png --compression lzw -o ${SO})
cmfilter_cli_case(NAME storage.bad.compression-level EXIT 3 STDERR "--compression 'zip:12' has an invalid level"
                  ABSENT ${SO} COMMAND ${CMF} bake-colormap ${LUTS}/terrain.png --compression zip:12 -o ${SO})
cmfilter_cli_case(NAME storage.bad.tile-zero EXIT 3 STDERR "--tile 0 5 is invalid \\(expected both sides in 1..4096\\)"
                  ABSENT ${SO} COMMAND ${CMF} bake-moments ${FIX}/driver-37x23.png --tile 0 5 -o ${SO})
cmfilter_cli_case(NAME storage.bad.tile-large EXIT 3 STDERR "--tile 8192 64 is invalid"
                  ABSENT ${SO} COMMAND ${CMF} bake-noise --noise fbm --tile 8192 64 -o ${SO})
cmfilter_cli_case(NAME storage.bad.tile-one-side EXIT 1 STDERR "--tile"
                  ABSENT ${SO} COMMAND ${CMF} bake-colormap ${LUTS}/terrain.png --tile 64 -o ${SO})
# -u/--update on the same commands (docs/storage.md#incremental-builds--u).
add_test(NAME cli.update
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/check_update.sh ${CMF} ${LUTS}/terrain.png ${FIX}/driver-4values.png
                 ${OUT}/update)
set_tests_properties(cli.update PROPERTIES FIXTURES_REQUIRED "cli_dirs;cli_fixtures" LABELS cli ENVIRONMENT "OCIO=")
