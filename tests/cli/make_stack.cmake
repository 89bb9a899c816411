# SPDX-License-Identifier: Apache-2.0
# make-stack: synthetic image stacks from a scene's microsurface.
cmfilter_cli_case(NAME help.make-stack EXIT 0 STDOUT "--dome" COMMAND ${CMF} make-stack --help)

set(MS ${OUT}/make-stack)
set(MSO ${MS}/bad.lp)
add_test(NAME cli.make-stack.setup COMMAND ${CMAKE_COMMAND} -E make_directory ${MS} ${MS}/btf ${MS}/held)
set_tests_properties(cli.make-stack.setup PROPERTIES FIXTURES_SETUP make_stack_dir FIXTURES_REQUIRED cli_dirs
                     LABELS cli)
# A good run, then its files; the ground truth at other lights from its record.
cmfilter_cli_case(NAME make-stack.good EXIT 0 STDOUT "wrote .*stack\\.lp: 1 view\\(s\\) x 8 lights, 16 x 16"
                  COMMAND ${CMF} make-stack ${EX}/stack-shiny-shadows.json -o ${MS}/stack.lp --size 16 --spp 4
                          --dome fibonacci:8 --specular blinn-phong:ks=0.2,n=40 --threads 2)
set_tests_properties(cli.make-stack.good PROPERTIES FIXTURES_SETUP make_stack_good FIXTURES_REQUIRED make_stack_dir)
add_test(NAME cli.make-stack.good-files
         COMMAND bash -c "set -e; cd $0; test $(head -1 stack.lp) = 8; test -f stack-000.exr; test -f stack-007.exr
test -f stack.normals.exr; grep -q '\"scene_sha256\"' stack.json; grep -q '\"specular\": \"blinn-phong:ks=0.2' stack.json"
                 ${MS})
set_tests_properties(cli.make-stack.good-files PROPERTIES FIXTURES_REQUIRED make_stack_good LABELS cli)
cmfilter_cli_case(NAME make-stack.from-record EXIT 0 STDOUT "\"lights\": 6"
                  COMMAND ${CMF} make-stack --from ${MS}/stack.json --dome regular:6 --min-elevation 30 --json
                          -o ${MS}/held/stack.lp)
set_tests_properties(cli.make-stack.from-record PROPERTIES FIXTURES_REQUIRED make_stack_good)
cmfilter_cli_case(NAME make-stack.btf EXIT 0 STDOUT "2 view\\(s\\) x 6 lights"
                  COMMAND ${CMF} make-stack ${EX}/stack-multiview.json -o ${MS}/btf/btf.json --size 8 --spp 1
                          --dome stage:6 --view 0,0,1 --view 0.5,0,0.866 --format png)
set_tests_properties(cli.make-stack.btf PROPERTIES FIXTURES_REQUIRED make_stack_dir)

# Bad input: exit code, message, nothing written.
foreach(bad IN ITEMS "fibonaci:64|unknown kind 'fibonaci'" "regular|has no ':'" "stage:6.5|no whole number of lights"
                     "file:|names no file")
  string(REPLACE "|" ";" pair "${bad}")
  list(GET pair 0 dome)
  list(GET pair 1 message)
  string(REGEX REPLACE "[^a-z0-9]+" "-" name "${dome}")
  cmfilter_cli_case(NAME make-stack.bad.dome-${name} EXIT 3 STDERR "dome '${dome}' .*${message}" ABSENT ${MSO}
                    COMMAND ${CMF} make-stack ${EX}/stack-near-diffuse.json --dome ${dome} -o ${MSO})
endforeach()
cmfilter_cli_case(NAME make-stack.bad.dome-file-missing EXIT 2 STDERR "no-such\\.lp" ABSENT ${MSO}
                  COMMAND ${CMF} make-stack ${EX}/stack-near-diffuse.json --dome file:${MS}/no-such.lp -o ${MSO})
cmfilter_cli_case(NAME make-stack.bad.few-lights EXIT 3 STDERR "--dome 'regular:5' has 5 light\\(s\\): a stack needs at least 6"
                  ABSENT ${MSO} COMMAND ${CMF} make-stack ${EX}/stack-near-diffuse.json --dome regular:5 -o ${MSO})
cmfilter_cli_case(NAME make-stack.bad.view-below EXIT 3 STDERR "--view '0.5,0,-0.2' is below the horizon"
                  ABSENT ${MSO} COMMAND ${CMF} make-stack ${EX}/stack-near-diffuse.json --view 0.5,0,-0.2 -o ${MSO})
cmfilter_cli_case(NAME make-stack.bad.view-horizon EXIT 3 STDERR "--view \\(1, 0, 0\\) is not above the horizon"
                  ABSENT ${MSO} COMMAND ${CMF} make-stack ${EX}/stack-near-diffuse.json --view 1,0,0 -o ${MSO})
cmfilter_cli_case(NAME make-stack.bad.view-zero EXIT 3 STDERR "--view '0,0,0' is zero"
                  ABSENT ${MSO} COMMAND ${CMF} make-stack ${EX}/stack-near-diffuse.json --view 0,0,0 -o ${MSO})
cmfilter_cli_case(NAME make-stack.bad.noise-surface EXIT 3
                  STDERR "plane-fbm-terrain\\.json: /surfaces/0: make-stack traces a Gaussian microsurface or a textured displacement, but its material is a colour map over a noise driver"
                  ABSENT ${MSO} COMMAND ${CMF} make-stack ${EX}/plane-fbm-terrain.json -o ${MSO})
cmfilter_cli_case(NAME make-stack.bad.size-zero EXIT 3 STDERR "--size 0 is invalid: expected 1 to 4096"
                  ABSENT ${MSO} COMMAND ${CMF} make-stack ${EX}/stack-near-diffuse.json --size 0 -o ${MSO})
cmfilter_cli_case(NAME make-stack.bad.spp-zero EXIT 3 STDERR "--spp 0 is invalid"
                  ABSENT ${MSO} COMMAND ${CMF} make-stack ${EX}/stack-near-diffuse.json --spp 0 -o ${MSO})
cmfilter_cli_case(NAME make-stack.bad.specular-kind EXIT 3 STDERR "specular lobe 'phong:ks=1' is of an unknown kind"
                  ABSENT ${MSO} COMMAND ${CMF} make-stack ${EX}/stack-near-diffuse.json --specular phong:ks=1 -o ${MSO})
cmfilter_cli_case(NAME make-stack.bad.specular-missing EXIT 3 STDERR "specular lobe 'ggx:ks=0.04' lacks alpha"
                  ABSENT ${MSO} COMMAND ${CMF} make-stack ${EX}/stack-near-diffuse.json --specular ggx:ks=0.04 -o ${MSO})
cmfilter_cli_case(NAME make-stack.bad.specular-range EXIT 3 STDERR "ggx:ks=1.5,alpha=0.2' is out of range"
                  ABSENT ${MSO} COMMAND ${CMF} make-stack ${EX}/stack-near-diffuse.json --specular ggx:ks=1.5,alpha=0.2 -o ${MSO})
cmfilter_cli_case(NAME make-stack.bad.min-elevation EXIT 3 STDERR "--min-elevation 85 is invalid"
                  ABSENT ${MSO} COMMAND ${CMF} make-stack ${EX}/stack-near-diffuse.json --dome regular:20 --min-elevation 85 -o ${MSO})
cmfilter_cli_case(NAME make-stack.bad.surface EXIT 3 STDERR "--surface 3 is invalid: the scene has 1 surface"
                  ABSENT ${MSO} COMMAND ${CMF} make-stack ${EX}/stack-near-diffuse.json --surface 3 -o ${MSO})
cmfilter_cli_case(NAME make-stack.bad.output-extension EXIT 3 STDERR "expected a \\.lp file"
                  ABSENT ${MS}/bad.png COMMAND ${CMF} make-stack ${EX}/stack-near-diffuse.json -o ${MS}/bad.png)
cmfilter_cli_case(NAME make-stack.bad.format EXIT 3 STDERR "--format 'tiff' is unknown"
                  ABSENT ${MSO} COMMAND ${CMF} make-stack ${EX}/stack-near-diffuse.json --format tiff -o ${MSO})
cmfilter_cli_case(NAME make-stack.bad.from-and-size EXIT 3 STDERR "--size cannot be given with --from"
                  ABSENT ${MSO} COMMAND ${CMF} make-stack --from ${MS}/stack.json --size 8 -o ${MSO})
cmfilter_cli_case(NAME make-stack.bad.no-scene EXIT 3 STDERR "make-stack needs a scene file"
                  ABSENT ${MSO} COMMAND ${CMF} make-stack -o ${MSO})
# The refusals write into the make-stack folder, which must exist (else the output is refused first).
foreach(t dome-fibonaci-64 dome-regular dome-stage-6-5 dome-file- dome-file-missing few-lights view-below
          view-horizon view-zero noise-surface size-zero spp-zero specular-kind specular-missing specular-range
          min-elevation surface output-extension format from-and-size no-scene)
  set_tests_properties(cli.make-stack.bad.${t} PROPERTIES FIXTURES_REQUIRED "cli_dirs;cli_fixtures;make_stack_dir")
endforeach()

# A run that fails after rendering leaves what was there before: the old,
# complete stack (its .lp, images and record, untouched), and no staging
# folder behind; the same for a BTF whose second slot's folder is a file.
add_test(NAME cli.make-stack.failure-keeps-old-stack
         COMMAND bash -c "set -u; d=$1/keep; rm -rf $d; mkdir -p $d/btf
$0 make-stack $2 -o $d/stack.lp --size 8 --spp 1 --dome fibonacci:8 -q || exit 1
before=$(sha256sum $d/stack.lp $d/stack-004.exr $d/stack.json)
rm $d/stack-005.exr; mkdir $d/stack-005.exr
$0 make-stack $2 -o $d/stack.lp --size 8 --spp 1 --dome regular:8 -q 2>/dev/null; test $? = 2 || exit 1
test \"$(sha256sum $d/stack.lp $d/stack-004.exr $d/stack.json)\" = \"$before\" || { echo 'old stack changed'; exit 1; }
touch $d/btf/view-01
$0 make-stack $2 -o $d/btf/btf.json --size 8 --spp 1 --dome fibonacci:8 --view 0,0,1 --view 0.5,0,0.866 -q 2>/dev/null; test $? = 2 || exit 1
test ! -e $d/btf/btf.json -a ! -e $d/btf/view-00 || { echo 'partial BTF left'; exit 1; }
if ls -a $d $d/btf | grep -q '\\.tmp-'; then echo 'staging folder left'; exit 1; fi"
                 ${CMF} ${OUT} ${EX}/stack-near-diffuse.json)
set_tests_properties(cli.make-stack.failure-keeps-old-stack PROPERTIES FIXTURES_REQUIRED cli_dirs LABELS cli
                     ENVIRONMENT "OCIO=")
