# SPDX-License-Identifier: Apache-2.0
# noise-image: a procedural noise driver written as an image.
cmfilter_cli_case(NAME help.noise-image EXIT 0 STDOUT "--scale" COMMAND ${CMF} noise-image --help)

cmfilter_cli_case(NAME noise-image.write EXIT 0 STDOUT "noise image, 64 x 32"
                  COMMAND ${CMF} noise-image --noise fbm:base=gradient,octaves=3,seed=5 --size 64x32
                          --scale 0.1 -o ${OUT}/noise.exr)
set_tests_properties(cli.noise-image.write PROPERTIES FIXTURES_SETUP noise_image)
cmfilter_cli_case(NAME noise-image.info EXIT 0
                  STDOUT "procedural noise driver \\(cmfilter noise-image\\): 64 x 32"
                  COMMAND ${CMF} info ${OUT}/noise.exr)
set_tests_properties(cli.noise-image.info PROPERTIES FIXTURES_REQUIRED "cli_dirs;noise_image")
add_test(NAME cli.noise-image.oiiotool-info COMMAND ${OIIOTOOL} --info -v ${OUT}/noise.exr)
set_tests_properties(cli.noise-image.oiiotool-info PROPERTIES FIXTURES_REQUIRED noise_image LABELS cli
    PASS_REGULAR_EXPRESSION "64 x +32, 1 channel, float.*channel list: Y")
set(NI ${OUT}/bad-noise.exr)
cmfilter_cli_case(NAME noise-image.bad.spec-key EXIT 3 STDERR "noise parameter.*octaves"
                  ABSENT ${NI} COMMAND ${CMF} noise-image --noise gradient:octaves=3 --size 8x8 -o ${NI})
cmfilter_cli_case(NAME noise-image.bad.spec-value EXIT 3 STDERR "noise parameter gain: 'abc' is not a finite number"
                  ABSENT ${NI} COMMAND ${CMF} noise-image --noise fbm:gain=abc --size 8x8 -o ${NI})
cmfilter_cli_case(NAME noise-image.bad.size EXIT 3 STDERR "--size '8y8' is not a size"
                  ABSENT ${NI} COMMAND ${CMF} noise-image --noise gradient --size 8y8 -o ${NI})
cmfilter_cli_case(NAME noise-image.bad.size-zero EXIT 3 STDERR "--size '0x8' is not a size"
                  ABSENT ${NI} COMMAND ${CMF} noise-image --noise gradient --size 0x8 -o ${NI})
cmfilter_cli_case(NAME noise-image.bad.scale EXIT 3 STDERR "--scale -1.0+ is invalid"
                  ABSENT ${NI} COMMAND ${CMF} noise-image --noise gradient --size 8x8 --scale=-1 -o ${NI})
# A noise image is a driver like any other.
cmfilter_cli_case(NAME noise-image.bake-moments EXIT 0 STDOUT "moment pyramid, 64 x 32"
                  COMMAND ${CMF} bake-moments ${OUT}/noise.exr -o ${OUT}/noise-moments.exr)
set_tests_properties(cli.noise-image.bake-moments PROPERTIES FIXTURES_REQUIRED "cli_dirs;noise_image")
