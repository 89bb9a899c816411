# SPDX-License-Identifier: Apache-2.0
# synth-analyse, synth, synth-apply: analyses, coordinate maps and renders
# through them; each bad input with its exit code and message and no output
# left behind. Samples from make_synth_fixtures.sh (and the stack fixtures).
set(SYF ${OUT}/synth-fixtures)
add_test(NAME cli.synth.fixtures
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/make_synth_fixtures.sh ${OIIOTOOL} ${STF} ${SYF})
set_tests_properties(cli.synth.fixtures PROPERTIES FIXTURES_SETUP synth_fixtures
                     FIXTURES_REQUIRED "cli_dirs;stack_fixtures" LABELS cli)

foreach(c IN ITEMS synth-analyse synth synth-apply)
  cmfilter_cli_case(NAME help.${c} EXIT 0 STDOUT "SAMPLE|COORDS" COMMAND ${CMF} ${c} --help)
endforeach()

# synth_case(NAME EXIT STDOUT|STDERR PATTERN OUTPUT COMMAND...): a case that
# needs the fixtures; OUTPUT must be absent afterwards when EXIT is not 0.
function(synth_case name code stream pattern output)
  if(code EQUAL 0)
    cmfilter_cli_case(NAME ${name} EXIT 0 ${stream} "${pattern}" COMMAND ${ARGN})
  else()
    cmfilter_cli_case(NAME ${name} EXIT ${code} ${stream} "${pattern}" ABSENT ${output} COMMAND ${ARGN})
  endif()
  set_tests_properties(cli.${name} PROPERTIES FIXTURES_REQUIRED "cli_dirs;stack_fixtures;synth_fixtures")
endfunction()

# The analysis, made once and reused.
set(SYA ${OUT}/synth-sample-analysis.exr)
synth_case(synth.analyse 0 STDOUT "wrote .*synth-sample-analysis\\.exr: 2 level" ${SYA}
           ${CMF} synth-analyse ${SYF}/sample.png -o ${SYA} --levels 2 --textons 64 --neighbourhood 1)
set_tests_properties(cli.synth.analyse PROPERTIES FIXTURES_SETUP synth_analysis)
synth_case(synth.info-analysis 0 STDOUT "synthesis-analysis" "" ${CMF} info ${SYA})
set_tests_properties(cli.synth.info-analysis PROPERTIES FIXTURES_REQUIRED "cli_dirs;synth_analysis")

set(SYM ${OUT}/synth-map.exr)
synth_case(synth.reuse 0 STDOUT "analysis reused from .*synth-sample-analysis\\.exr" ${SYM}
           ${CMF} synth ${SYF}/sample.png --analysis ${SYA} -o ${SYM} --size 40x30 -k 3 --levels 2
           --preview ${OUT}/synth-preview.png)
set_tests_properties(cli.synth.reuse PROPERTIES FIXTURES_REQUIRED "cli_dirs;synth_fixtures;synth_analysis"
                     FIXTURES_SETUP synth_map)
synth_case(synth.info-map 0 STDOUT "coordinate map of a synthesised surface.*40 x 30 texels" "" ${CMF} info ${SYM})
set_tests_properties(cli.synth.info-map PROPERTIES FIXTURES_REQUIRED "cli_dirs;synth_map")

# The same map for any thread count, and the preview equal to synth-apply's
# full-size render of the same image.
set(SYT ${OUT}/synth-threads)
add_test(NAME cli.synth.threads
         COMMAND bash -c "set -e; d=$0; mkdir -p $d; for t in 1 2; do $1 synth $2 -o $d/map-$t.exr --size 33x21 -k 2 --levels 2 --textons 32 --neighbourhood 1 --toroidal --seed 7 --threads $t -q; done; $3 -fail 0 $d/map-1.exr $d/map-2.exr"
                 ${SYT} $<TARGET_FILE:cmfilter_cli> ${SYF}/sample.png ${IDIFF})
set_tests_properties(cli.synth.threads PROPERTIES FIXTURES_REQUIRED "cli_dirs;synth_fixtures" LABELS cli)
synth_case(synth.apply-image 0 STDOUT "wrote .*synth-apply\\.png" ""
           ${CMF} synth-apply ${SYM} --source ${SYF}/sample.png -o ${OUT}/synth-apply.png)
set_tests_properties(cli.synth.apply-image PROPERTIES FIXTURES_REQUIRED "cli_dirs;synth_fixtures;synth_map"
                     FIXTURES_SETUP synth_apply)
add_test(NAME cli.synth.preview-matches-apply
         COMMAND ${IDIFF} -fail 0 ${OUT}/synth-preview.png ${OUT}/synth-apply.png)
set_tests_properties(cli.synth.preview-matches-apply PROPERTIES FIXTURES_REQUIRED "cli_dirs;synth_apply" LABELS cli)
foreach(m IN ITEMS reference naive point levels patches)
  synth_case(synth.apply-lod-${m} 0 STDOUT "20 x 15 \\(LOD 1, ${m}\\)" ""
             ${CMF} synth-apply ${SYM} --source ${SYF}/sample.png --lod 1 --lod-method ${m}
             -o ${OUT}/synth-apply-lod-${m}.exr)
  set_tests_properties(cli.synth.apply-lod-${m} PROPERTIES FIXTURES_REQUIRED "cli_dirs;synth_fixtures;synth_map")
endforeach()

# A stack and a BTF as samples, and a fit of the stack relit through the map.
synth_case(synth.stack 0 STDOUT "wrote .*synth-stack-map\\.exr: 20 x 20" ""
           ${CMF} synth ${STF}/good.lp -o ${OUT}/synth-stack-map.exr --size 20x20 --textons 4 --neighbourhood 1
           --quality)
set_tests_properties(cli.synth.stack PROPERTIES FIXTURES_REQUIRED "cli_dirs;stack_fixtures" FIXTURES_SETUP synth_stack)
synth_case(synth.btf 0 STDOUT "wrote .*synth-btf-map\\.exr: 16 x 16" ""
           ${CMF} synth ${SYF}/btf.json -o ${OUT}/synth-btf-map.exr --size 16x16 --textons 4 --neighbourhood 1)
synth_case(synth.apply-fit 0 STDOUT "through .*synth-stack-map\\.exr, 20 x 20" ""
           ${CMF} synth-apply ${OUT}/synth-stack-map.exr --source ${OUT}/fit-good-ptm-rgb.exr --light 0.3,0.2,0.93
           -o ${OUT}/synth-apply-fit.exr)
set_tests_properties(cli.synth.apply-fit PROPERTIES
                     FIXTURES_REQUIRED "cli_dirs;stack_fixtures;synth_stack;fit_good_ptm-rgb")
synth_case(synth.apply-stack-light 0 STDOUT "through .*synth-stack-map\\.exr, 20 x 20" ""
           ${CMF} synth-apply ${OUT}/synth-stack-map.exr --source ${STF}/good.lp --light 0,0.8,0.6
           -o ${OUT}/synth-apply-stack.exr)
set_tests_properties(cli.synth.apply-stack-light PROPERTIES FIXTURES_REQUIRED "cli_dirs;stack_fixtures;synth_stack")

# Bad input.
set(SYB ${OUT}/synth-bad.exr)
synth_case(bad.synth-missing 2 STDERR "no-such\\.png" ${SYB} ${CMF} synth ${SYF}/no-such.png -o ${SYB})
synth_case(bad.synth-empty 3 STDERR "empty\\.png' is empty" ${SYB} ${CMF} synth ${SYF}/empty.png -o ${SYB})
synth_case(bad.synth-stack-sizes 3 STDERR "wide\\.png' is 9x8 but .*img-0\\.png' is 8x8" ${SYB}
           ${CMF} synth ${STF}/size.lp -o ${SYB})
synth_case(bad.synth-k 3 STDERR "-k 0" ${SYB} ${CMF} synth ${SYF}/sample.png -o ${SYB} -k 0 --textons 16)
synth_case(bad.synth-neighbourhood 3 STDERR "--neighbourhood 20" ${SYB}
           ${CMF} synth ${SYF}/sample.png -o ${SYB} --neighbourhood 20 --textons 16)
synth_case(bad.synth-textons 3 STDERR "--textons 5000" ${SYB} ${CMF} synth ${SYF}/sample.png -o ${SYB} --textons 5000)
synth_case(bad.synth-size-zero 3 STDERR "--size '0x10'" ${SYB} ${CMF} synth ${SYF}/sample.png -o ${SYB} --size 0x10)
synth_case(bad.synth-size-limit 3 STDERR "--size.*20000.*16384" ${SYB}
           ${CMF} synth ${SYF}/sample.png -o ${SYB} --size 20000x16 --textons 16)
synth_case(bad.synth-hash 3 STDERR "made from another sample" ${SYB}
           ${CMF} synth ${SYF}/other.png --analysis ${SYA} -o ${SYB})
set_tests_properties(cli.bad.synth-hash PROPERTIES FIXTURES_REQUIRED "cli_dirs;synth_fixtures;synth_analysis")
synth_case(bad.synth-analysis-flag 3 STDERR "--textons sets how an analysis is made" ${SYB}
           ${CMF} synth ${SYF}/sample.png --analysis ${SYA} --textons 8 -o ${SYB})
set_tests_properties(cli.bad.synth-analysis-flag PROPERTIES FIXTURES_REQUIRED "cli_dirs;synth_fixtures;synth_analysis")
synth_case(bad.synth-analyse-textons 3 STDERR "--textons 5000" ${OUT}/synth-bad-analysis.exr
           ${CMF} synth-analyse ${SYF}/sample.png -o ${OUT}/synth-bad-analysis.exr --textons 5000)
synth_case(bad.synth-analyse-candidates 3 STDERR "--candidates 0" ${OUT}/synth-bad-analysis.exr
           ${CMF} synth-analyse ${SYF}/sample.png -o ${OUT}/synth-bad-analysis.exr --candidates 0)
set(SYP ${OUT}/synth-apply-bad.exr)
synth_case(bad.synth-apply-hash 3 STDERR "synthesised from another sample" ${SYP}
           ${CMF} synth-apply ${SYM} --source ${SYF}/other.png -o ${SYP})
set_tests_properties(cli.bad.synth-apply-hash PROPERTIES FIXTURES_REQUIRED "cli_dirs;synth_fixtures;synth_map")
synth_case(bad.synth-apply-smaller 3 STDERR "points into a 24 x 24 sample, but .*small\\.png' is 12 x 12" ${SYP}
           ${CMF} synth-apply ${SYM} --source ${SYF}/small.png --no-hash-check -o ${SYP})
set_tests_properties(cli.bad.synth-apply-smaller PROPERTIES FIXTURES_REQUIRED "cli_dirs;synth_fixtures;synth_map")
synth_case(bad.synth-apply-outside 3 STDERR "map-outside\\.exr.*outside the sample" ${SYP}
           ${CMF} synth-apply ${SYF}/map-outside.exr --source ${SYF}/sample.png --no-hash-check -o ${SYP})
synth_case(bad.synth-apply-method 3 STDERR "'blur'" ${SYP}
           ${CMF} synth-apply ${SYF}/map-inside.exr --source ${SYF}/sample.png -o ${SYP} --lod-method blur)
synth_case(bad.synth-apply-lod 3 STDERR "--lod -1" ${SYP}
           ${CMF} synth-apply ${SYF}/map-inside.exr --source ${SYF}/sample.png --no-hash-check -o ${SYP} --lod -1)
synth_case(bad.synth-apply-image 3 STDERR "--image 99" ${SYP}
           ${CMF} synth-apply ${SYF}/map-inside.exr --source ${SYF}/sample.png --no-hash-check -o ${SYP} --image 99)
synth_case(bad.synth-apply-levels 3 STDERR "--lod 3.*levels" ${SYP}
           ${CMF} synth-apply ${SYF}/map-inside.exr --source ${SYF}/sample.png --no-hash-check -o ${SYP} --lod 3
           --lod-method levels)
