# SPDX-License-Identifier: Apache-2.0
# The binary itself: its version, its help, and usage errors before any command runs.
cmfilter_cli_case(NAME version EXIT 0 STDOUT "^cmfilter [0-9]+\\.[0-9]+\\.[0-9]+" COMMAND ${CMF} --version)
cmfilter_cli_case(NAME help EXIT 0 STDOUT "bake-colormap" COMMAND ${CMF} --help)
# No command, and an option the command does not know.
cmfilter_cli_case(NAME usage.no-command EXIT 1 STDERR "^cmfilter: error: " COMMAND ${CMF})
cmfilter_cli_case(NAME usage.unknown-option EXIT 1 STDERR "^cmfilter bake-colormap: error: .*--bogus"
                  ABSENT ${OUT}/usage.exr
                  COMMAND ${CMF} bake-colormap ${LUTS}/terrain.png -o ${OUT}/usage.exr --bogus)
