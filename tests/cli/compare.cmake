# SPDX-License-Identifier: Apache-2.0
# compare: two images' CIEDE2000 differences and their heat map.
cmfilter_cli_case(NAME help.compare EXIT 0 STDOUT "--heatmap-max" COMMAND ${CMF} compare --help)

# --- compare: bad input, each with its exit code, message and no heat map ------
set(H ${OUT}/bad-heat.png)
set(CA ${FIX}/cmp-a.exr)
set(CB ${FIX}/cmp-b.exr)
cmfilter_cli_case(NAME compare.bad.missing-file EXIT 2 STDERR "^cmfilter compare: error: cannot read '.*no-such\\.exr': no such file"
                  ABSENT ${H} COMMAND ${CMF} compare ${CA} ${FIX}/no-such.exr --heatmap ${H})
cmfilter_cli_case(NAME compare.bad.not-an-image EXIT 3 STDERR "not-an-image\\.png' is not an image OpenImageIO can read"
                  ABSENT ${H} COMMAND ${CMF} compare ${FIX}/not-an-image.png ${CB} --heatmap ${H})
cmfilter_cli_case(NAME compare.bad.size-mismatch EXIT 3
                  STDERR "cmp-a\\.exr' is 16 x 8 but '.*cmp-small\\.exr' is 8 x 8; expected images of the same size"
                  ABSENT ${H} COMMAND ${CMF} compare ${CA} ${FIX}/cmp-small.exr --heatmap ${H})
cmfilter_cli_case(NAME compare.bad.unknown-colorspace EXIT 3
                  STDERR "unknown colour space 'bogus'.*known colour spaces:"
                  ABSENT ${H} COMMAND ${CMF} compare ${CA} ${CB} --colorspace-b bogus --heatmap ${H})
cmfilter_cli_case(NAME compare.bad.heatmap-directory-missing EXIT 2
                  STDERR "cannot write '.*no-such-dir/heat\\.png': directory '.*no-such-dir' does not exist"
                  ABSENT ${OUT}/no-such-dir/heat.png
                  COMMAND ${CMF} compare ${CA} ${CB} --heatmap ${OUT}/no-such-dir/heat.png)
cmfilter_cli_case(NAME compare.bad.heatmap-extension EXIT 3
                  STDERR "output '.*heat\\.exr' has the wrong extension \\(expected a \\.png file\\)"
                  ABSENT ${OUT}/heat.exr COMMAND ${CMF} compare ${CA} ${CB} --heatmap ${OUT}/heat.exr)
cmfilter_cli_case(NAME compare.bad.heatmap-max-zero EXIT 3
                  STDERR "--heatmap-max 0 is invalid \\(expected a finite Delta E00 > 0\\)"
                  ABSENT ${H} COMMAND ${CMF} compare ${CA} ${CB} --heatmap ${H} --heatmap-max 0)
cmfilter_cli_case(NAME compare.bad.nan-texel EXIT 3
                  STDERR "nan\\.exr' has 1 pixel with non-finite values \\(the first at \\(1, 0\\) channel 0: nan\\); expected finite colours"
                  ABSENT ${H} COMMAND ${CMF} compare ${FIX}/nan.exr ${FIX}/inf.exr --heatmap ${H})
cmfilter_cli_case(NAME compare.bad.inf-texel EXIT 3
                  STDERR "inf\\.exr' has 1 pixel with non-finite values \\(the first at \\(2, 0\\) channel 2: inf\\)"
                  ABSENT ${H} COMMAND ${CMF} compare ${FIX}/ramp.png ${FIX}/inf.exr --heatmap ${H})
cmfilter_cli_case(NAME compare.usage.heatmap-max-without-heatmap EXIT 1 STDERR "--heatmap-max requires --heatmap"
                  COMMAND ${CMF} compare ${CA} ${CB} --heatmap-max 5)
cmfilter_cli_case(NAME compare.usage.missing-b EXIT 1 STDERR "^cmfilter compare: error: .*B"
                  COMMAND ${CMF} compare ${CA})

# --- compare: results ----------------------------------------------------------
# RMSE against OpenImageIO's own (oiiotool --diff) on float images with HDR and
# negative values (float files are linear: no conversion on either side).
add_test(NAME cli.compare.rmse-vs-oiiotool
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/check_rmse_vs_oiiotool.sh ${CMF} ${OIIOTOOL} ${CA} ${CB})
set_tests_properties(cli.compare.rmse-vs-oiiotool PROPERTIES FIXTURES_REQUIRED cli_fixtures LABELS cli
                     ENVIRONMENT "OCIO=")
# An image against itself: zero everywhere (exact: every difference is 0).
cmfilter_cli_case(NAME compare.identical EXIT 0
                  STDOUT "dE2000 max +0$"
                  COMMAND ${CMF} compare ${CA} ${CA})
cmfilter_cli_case(NAME compare.json EXIT 0
                  STDOUT "\"ciede2000\": \\{"
                  COMMAND ${CMF} compare ${CA} ${CB} --json)
# The heat map is an 8-bit PNG of the images' size that OpenImageIO reads.
cmfilter_cli_case(NAME compare.heatmap EXIT 0 STDOUT "wrote .*heat\\.png: CIEDE2000 heat map"
                  COMMAND ${CMF} compare ${CA} ${CB} --heatmap ${OUT}/heat.png)
set_tests_properties(cli.compare.heatmap PROPERTIES FIXTURES_SETUP compare_heatmap)
add_test(NAME cli.compare.heatmap-info COMMAND ${OIIOTOOL} --info ${OUT}/heat.png)
set_tests_properties(cli.compare.heatmap-info PROPERTIES FIXTURES_REQUIRED compare_heatmap LABELS cli
    PASS_REGULAR_EXPRESSION "16 x +8, 3 channel, uint8 png")

# Build gates: --warn, --fail and --gate, with their own exit codes.
add_test(NAME cli.compare.gates COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/check_compare_gates.sh ${CMF} ${CA} ${CB})
set_tests_properties(cli.compare.gates PROPERTIES FIXTURES_REQUIRED cli_fixtures LABELS cli ENVIRONMENT "OCIO=")
