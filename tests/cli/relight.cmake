# SPDX-License-Identifier: Apache-2.0
# relight and normals: fits evaluated under a light, measured against a
# stack, and their normals; bad input with its exit code and message.
cmfilter_cli_case(NAME help.relight EXIT 0 STDOUT "FIT" COMMAND ${CMF} relight --help)
cmfilter_cli_case(NAME help.normals EXIT 0 STDOUT "FIT" COMMAND ${CMF} normals --help)

foreach(f IN ITEMS fit-good-ptm-rgb.exr fit-good.ptm fit-good.rti)
  string(REPLACE "." "-" n ${f})
  cmfilter_cli_case(NAME relight.${n} EXIT 0 STDOUT "relit at" COMMAND ${CMF} relight ${OUT}/${f} --light 0.3,0.2,0.9
                    -o ${OUT}/relit-${n}.png)
  cmfilter_cli_case(NAME relight.reference-${n} EXIT 0 STDOUT "CIEDE2000 mean"
                    COMMAND ${CMF} relight ${OUT}/${f} --reference ${STF}/good.lp)
endforeach()
set_tests_properties(cli.relight.fit-good-ptm-rgb-exr cli.relight.reference-fit-good-ptm-rgb-exr
                     PROPERTIES FIXTURES_REQUIRED "cli_dirs;stack_fixtures;fit_good_ptm-rgb")
set_tests_properties(cli.relight.fit-good-ptm cli.relight.reference-fit-good-ptm
                     PROPERTIES FIXTURES_REQUIRED "cli_dirs;stack_fixtures;fit_good_ptm")
set_tests_properties(cli.relight.fit-good-rti cli.relight.reference-fit-good-rti
                     PROPERTIES FIXTURES_REQUIRED "cli_dirs;stack_fixtures;fit_good_rti")

# The relit PNG of a constant stack's fits holds the stack's own 8-bit codes
# (idiff: within one code), from the .ptm, the .rti and the EXR alike.
find_program(IDIFF idiff REQUIRED)
foreach(f IN ITEMS fit-good.ptm fit-good.rti fit-good-ptm-lrgb.exr)
  string(REPLACE "." "-" n ${f})
  add_test(NAME cli.relight.png-codes-${n}
           COMMAND bash -c "$0 relight $1/$3 --light -0.4,0.5,0.77 -o $1/relit-codes-$3.png -q && $2 -fail 0.0041 $1/relit-codes-$3.png $4/img-0.png"
                   ${CMF} ${OUT} ${IDIFF} ${f} ${STF})
  set_tests_properties(cli.relight.png-codes-${n} PROPERTIES FIXTURES_REQUIRED "cli_dirs;stack_fixtures;fit_good_ptm;fit_good_rti;fit_good_ptm-lrgb" LABELS cli ENVIRONMENT "OCIO=")
endforeach()

cmfilter_cli_case(NAME bad.relight-light EXIT 3 STDERR "--light '1,2' is not a direction" ABSENT ${OUT}/relit-bad.exr
                  COMMAND ${CMF} relight ${OUT}/fit-good-ptm-rgb.exr --light 1,2 -o ${OUT}/relit-bad.exr)
cmfilter_cli_case(NAME bad.relight-below EXIT 3 STDERR "--light '0,0,-1' is below the horizon"
                  ABSENT ${OUT}/relit-bad.exr
                  COMMAND ${CMF} relight ${OUT}/fit-good-ptm-rgb.exr --light 0,0,-1 -o ${OUT}/relit-bad.exr)
cmfilter_cli_case(NAME bad.relight-nothing EXIT 3 STDERR "needs either --light"
                  COMMAND ${CMF} relight ${OUT}/fit-good-ptm-rgb.exr)
cmfilter_cli_case(NAME bad.relight-not-fit EXIT 3 STDERR "terrain\\.png"
                  ABSENT ${OUT}/relit-bad.exr COMMAND ${CMF} relight ${LUTS}/terrain.png --light 0,0,1 -o ${OUT}/relit-bad.exr)
cmfilter_cli_case(NAME bad.relight-reference-size EXIT 3 STDERR "is 4x4 with 3; expected the same size and channels"
                  COMMAND ${CMF} relight ${OUT}/fit-good-ptm-rgb.exr --reference ${STF}/small.lp)
set_tests_properties(cli.bad.relight-light cli.bad.relight-below cli.bad.relight-nothing cli.bad.relight-reference-size
                     PROPERTIES FIXTURES_REQUIRED "cli_dirs;stack_fixtures;fit_good_ptm-rgb")

cmfilter_cli_case(NAME normals.ptm EXIT 0 STDOUT "texels without an interior maximum"
                  COMMAND ${CMF} normals ${OUT}/fit-good-ptm-rgb.exr -o ${OUT}/normals-good.exr)
set_tests_properties(cli.normals.ptm PROPERTIES FIXTURES_REQUIRED "cli_dirs;fit_good_ptm-rgb")
cmfilter_cli_case(NAME bad.normals-nothing EXIT 3 STDERR "normals needs -o" COMMAND ${CMF} normals ${OUT}/fit-good-ptm-rgb.exr)
cmfilter_cli_case(NAME bad.normals-extension EXIT 3 STDERR "\\.exr" ABSENT ${OUT}/normals-bad.png
                  COMMAND ${CMF} normals ${OUT}/fit-good-ptm-rgb.exr -o ${OUT}/normals-bad.png)
set_tests_properties(cli.bad.normals-nothing cli.bad.normals-extension PROPERTIES FIXTURES_REQUIRED "cli_dirs;fit_good_ptm-rgb")

# .ptm and .rti files that are cut short or of a kind not supported are
# refused by every command that reads a fit.
add_test(NAME cli.relight.setup-bad-files
         COMMAND bash -c "set -e; head -c 600 $0/fit-good.ptm > $0/fit-truncated.ptm; head -c 300 $0/fit-good.rti > $0/fit-truncated.rti
printf 'PTM_1.2\\nPTM_FORMAT_JPEG_RGB\\n8\\n8\\n' > $0/fit-jpeg.ptm" ${OUT})
set_tests_properties(cli.relight.setup-bad-files PROPERTIES FIXTURES_REQUIRED "cli_dirs;fit_good_ptm;fit_good_rti"
                     FIXTURES_SETUP bad_fit_files LABELS cli)
cmfilter_cli_case(NAME bad.relight-truncated-ptm EXIT 3 STDERR "fit-truncated\\.ptm' is truncated: expected [0-9]+ bytes"
                  ABSENT ${OUT}/relit-bad.png
                  COMMAND ${CMF} relight ${OUT}/fit-truncated.ptm --light 0,0,1 -o ${OUT}/relit-bad.png)
cmfilter_cli_case(NAME bad.normals-truncated-rti EXIT 3 STDERR "fit-truncated\\.rti' is truncated"
                  ABSENT ${OUT}/normals-bad.exr
                  COMMAND ${CMF} normals ${OUT}/fit-truncated.rti -o ${OUT}/normals-bad.exr)
cmfilter_cli_case(NAME bad.info-jpeg-ptm EXIT 3 STDERR "PTM_FORMAT_JPEG_RGB, which cmfilter does not support"
                  COMMAND ${CMF} info ${OUT}/fit-jpeg.ptm)
set_tests_properties(cli.bad.relight-truncated-ptm cli.bad.normals-truncated-rti cli.bad.info-jpeg-ptm
                     PROPERTIES FIXTURES_REQUIRED "cli_dirs;bad_fit_files")
add_test(NAME cli.bad.normals-zero-reference
         COMMAND bash -c "$2 --pattern constant:color=0,0,0 8x8 3 -d float -o $1/zero-normals.exr && bash $3 --exit 3 --stderr 'zero or non-finite at every texel' -- $0 normals $1/fit-good-ptm-rgb.exr --reference $1/zero-normals.exr"
                 ${CMF} ${OUT} ${OIIOTOOL} ${RUN})
set_tests_properties(cli.bad.normals-zero-reference PROPERTIES FIXTURES_REQUIRED "cli_dirs;fit_good_ptm-rgb" LABELS cli
                     ENVIRONMENT "OCIO=")
