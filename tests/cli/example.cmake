# SPDX-License-Identifier: Apache-2.0
# The library's examples, run on what the command-line tests bake.

# The library example reads a table back and looks it up. v = 0.5 lies midway
# between value nodes 127 (v = 0.4951, inside dark-red stripe 3) and 128
# (v = 0.5049, inside pale-cyan stripe 4), and at sigma = 0 those nodes are the
# stripe colours, so the lookup is their mean: sRGB codes (120,10,20) and
# (170,235,240) decoded and averaged give (0.29490, 0.41690, 0.43918); the
# pattern allows 1e-4 for float32 storage and printing to 6 digits.
add_test(NAME cli.example.lookup-table
         COMMAND $<TARGET_FILE:cmfilter_example_lookup_table> ${OUT}/stripes.exr 0.5 0)
set_tests_properties(cli.example.lookup-table PROPERTIES FIXTURES_REQUIRED table_stripes LABELS cli
    PASS_REGULAR_EXPRESSION "^0\\.294(8|9)[0-9]* 0\\.416(8|9)[0-9]* 0\\.439(1|2)[0-9]*")
