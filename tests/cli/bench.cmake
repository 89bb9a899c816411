# SPDX-License-Identifier: Apache-2.0
# bench: speed against accuracy on scenes.
cmfilter_cli_case(NAME help.bench EXIT 0 STDOUT "--reference-spp" COMMAND ${CMF} bench --help)

cmfilter_cli_case(NAME bench.small EXIT 0 STDOUT "wrote .*bench\\.csv: 1 scene"
                  COMMAND ${CMF} bench ${SC}/good.json --csv ${OUT}/bench.csv --charts ${OUT}
                          --resolution 24x14 --repeats 1)
set_tests_properties(cli.bench.small PROPERTIES FIXTURES_SETUP bench_csv)
add_test(NAME cli.bench.csv-rows COMMAND grep -c "good.json," ${OUT}/bench.csv)
set_tests_properties(cli.bench.csv-rows PROPERTIES FIXTURES_REQUIRED bench_csv LABELS cli
    PASS_REGULAR_EXPRESSION "^22\n")
add_test(NAME cli.bench.chart COMMAND ${CMAKE_COMMAND} -E cat ${OUT}/good.png)
set_tests_properties(cli.bench.chart PROPERTIES FIXTURES_REQUIRED bench_csv LABELS cli)
add_test(NAME cli.bench.chart-bytes COMMAND ${CMAKE_COMMAND} -E cat ${OUT}/good-bytes.png)
set_tests_properties(cli.bench.chart-bytes PROPERTIES FIXTURES_REQUIRED bench_csv LABELS cli)
# driver_bytes: the scene's sigma table as stored, 45 float32 nodes
# (oiiotool --info: 45 x 1) for the filtered methods, nothing for the
# procedural noise's supersampling.
add_test(NAME cli.bench.driver-bytes
         COMMAND bash -c "grep -c '^[^,]*good.json,\\(gaussian 256x256 sqrt\\|mixture\\|naive\\),.*,180$' $0 && grep -c '^[^,]*good.json,supersample 4,.*,0$' $0"
                 ${OUT}/bench.csv)
set_tests_properties(cli.bench.driver-bytes PROPERTIES FIXTURES_REQUIRED bench_csv LABELS cli
    PASS_REGULAR_EXPRESSION "^3\n1\n")
# Every row has the header's columns.
add_test(NAME cli.bench.csv-columns
         COMMAND bash -c "awk -F, 'NR == 1 { n = NF } NF != n { bad = 1 } END { exit bad }' $0" ${OUT}/bench.csv)
set_tests_properties(cli.bench.csv-columns PROPERTIES FIXTURES_REQUIRED bench_csv LABELS cli)
# exact runs on a scene whose driver has four values (one row), and is left
# out on the noise scene above. The configurations the summary
# reads, not the tolerance bakes bench.small times.
cmfilter_cli_case(NAME bench.texture-exact EXIT 0 STDOUT "wrote .*bench-texture\\.csv: 1 scene"
                  COMMAND ${CMF} bench ${SCB}/texture-quantised.json --csv ${OUT}/bench-texture.csv
                          --resolution 16x9 --repeats 1
                          --only "naive,exact,gaussian 256x256 sqrt,supersample 1,supersample 4,supersample 16")
set_tests_properties(cli.bench.texture-exact PROPERTIES FIXTURES_SETUP bench_texture_csv)
add_test(NAME cli.bench.texture-exact-row COMMAND grep -c ",exact,exact,1,,,,rms,0," ${OUT}/bench-texture.csv)
set_tests_properties(cli.bench.texture-exact-row PROPERTIES FIXTURES_REQUIRED bench_texture_csv LABELS cli
    PASS_REGULAR_EXPRESSION "^1\n")
add_test(NAME cli.bench.texture-summary COMMAND python3 ${PROJECT_SOURCE_DIR}/tests/bench/render_bench_summary.py
                                                ${OUT}/bench-texture.csv)
set_tests_properties(cli.bench.texture-summary PROPERTIES FIXTURES_REQUIRED bench_texture_csv LABELS cli
    PASS_REGULAR_EXPRESSION "texture-quantised\\.json \\| [0-9.]+ \\([0-9.]+ / [0-9.]+ / [0-9.]+\\) \\| [0-9.]+ \\|")
cmfilter_cli_case(NAME bench.no-edge-coverage EXIT 0 STDOUT "wrote .*bench-no-edges\\.csv: 1 scene"
                  COMMAND ${CMF} bench ${SC}/good.json --csv ${OUT}/bench-no-edges.csv --no-edge-coverage
                          --resolution 16x9 --repeats 1 --only "naive,gaussian 256x256 sqrt,supersample 4")
cmfilter_cli_case(NAME bench.bad.reference-spp EXIT 3 STDERR "--reference-spp 100 is out of range"
                  ABSENT ${OUT}/bench-bad.csv
                  COMMAND ${CMF} bench ${SC}/good.json --csv ${OUT}/bench-bad.csv --reference-spp 100)
cmfilter_cli_case(NAME bench.bad.reference-repeat EXIT 3 STDERR "--reference-repeat -0.5.* is out of range"
                  ABSENT ${OUT}/bench-bad.csv
                  COMMAND ${CMF} bench ${SC}/good.json --csv ${OUT}/bench-bad.csv --reference-repeat -0.5)
cmfilter_cli_case(NAME bench.bad.max-reference-spp EXIT 3 STDERR "--max-reference-spp 1500 is out of range"
                  ABSENT ${OUT}/bench-bad.csv
                  COMMAND ${CMF} bench ${SC}/good.json --csv ${OUT}/bench-bad.csv --reference-spp 2048
                          --max-reference-spp 1500)
cmfilter_cli_case(NAME bench.bad.only EXIT 3 STDERR "configuration 'gaussian 7x7 sqrt' is unknown .*'naive'"
                  ABSENT ${OUT}/bench-bad.csv
                  COMMAND ${CMF} bench ${SC}/good.json --csv ${OUT}/bench-bad.csv --only "naive,gaussian 7x7 sqrt")
cmfilter_cli_case(NAME bench.only EXIT 0 STDOUT "wrote .*bench-only\\.csv: 1 scene"
                  COMMAND ${CMF} bench ${SC}/good.json --csv ${OUT}/bench-only.csv --resolution 24x14 --repeats 1
                          --only "supersample 4,naive")
set_tests_properties(cli.bench.only PROPERTIES FIXTURES_SETUP bench_only_csv)
add_test(NAME cli.bench.only-rows COMMAND grep -c "good.json,\\(naive\\|supersample 4\\)," ${OUT}/bench-only.csv)
set_tests_properties(cli.bench.only-rows PROPERTIES FIXTURES_REQUIRED bench_only_csv LABELS cli
    PASS_REGULAR_EXPRESSION "^2\n")
cmfilter_cli_case(NAME bench.bad.charts-folder EXIT 2 STDERR "--charts '.*no-such-dir' is not a folder"
                  ABSENT ${OUT}/bench-bad.csv
                  COMMAND ${CMF} bench ${SC}/good.json --csv ${OUT}/bench-bad.csv --charts ${OUT}/no-such-dir)
# --region (docs/farm.md): refused as render refuses it; --references must
# be a folder. Regions of bench's references stitched: tests/cli/farm.cmake.
cmfilter_cli_case(NAME bench.bad.region-outside EXIT 3
                  STDERR "good\\.json: --region 0,0,40,18 lies outside the frame \\(expected .* in the 32 x 18 frame"
                  ABSENT ${OUT}/bench-bad.csv
                  COMMAND ${CMF} bench ${SC}/good.json --csv ${OUT}/bench-bad.csv --region 0,0,40,18)
cmfilter_cli_case(NAME bench.bad.region-malformed EXIT 3 STDERR "--region '0;0;8;8' is not a region"
                  ABSENT ${OUT}/bench-bad.csv
                  COMMAND ${CMF} bench ${SC}/good.json --csv ${OUT}/bench-bad.csv --region "0;0;8;8")
cmfilter_cli_case(NAME bench.bad.references-folder EXIT 2 STDERR "--references '.*no-such-dir' is not a folder"
                  ABSENT ${OUT}/bench-bad.csv
                  COMMAND ${CMF} bench ${SC}/good.json --csv ${OUT}/bench-bad.csv --references ${OUT}/no-such-dir)
