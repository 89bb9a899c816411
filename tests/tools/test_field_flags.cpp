// SPDX-License-Identifier: Apache-2.0
// The command line's messages: library messages name options fields
// ("ApplyOptions::lod"), and name_flags writes each as the command's flag,
// only where the whole field name stands, the longest field first.
#include "command.h"

#include <doctest/doctest.h>

using cmfilter::cli::FieldFlags;
using cmfilter::cli::name_flags;

TEST_CASE("name_flags writes each field a message names as its flag, every time it stands")
{
    const FieldFlags flags{{"ApplyOptions::lod", "--lod"}, {"ApplyOptions::method", "--method"}};
    CHECK(name_flags("ApplyOptions::lod nan is invalid (expected a finite number)", flags) ==
          "--lod nan is invalid (expected a finite number)");
    CHECK(name_flags("ApplyOptions::method exact needs ApplyOptions::lod >= 0; ApplyOptions::lod 3", flags) ==
          "--method exact needs --lod >= 0; --lod 3");
    CHECK(name_flags("no field here", flags) == "no field here");
    CHECK(name_flags("ApplyOptions::lod 1", {}) == "ApplyOptions::lod 1");
    CHECK(name_flags("", flags).empty());
}

TEST_CASE("name_flags replaces only whole field names")
{
    const FieldFlags flags{{"ApplyOptions::lod", "--lod"}};
    CHECK(name_flags("ApplyOptions::lods 1", flags) == "ApplyOptions::lods 1");
    CHECK(name_flags("ApplyOptions::lod_bias 1", flags) == "ApplyOptions::lod_bias 1");
    CHECK(name_flags("MyApplyOptions::lod 1", flags) == "MyApplyOptions::lod 1");
    CHECK(name_flags("(ApplyOptions::lod)", flags) == "(--lod)");
    CHECK(name_flags("ends with ApplyOptions::lod", flags) == "ends with --lod");
}

TEST_CASE("name_flags takes the longest field first, and keeps a value's placeholder")
{
    const FieldFlags flags{{"Options::range", "--range"}, {"Options::range_max", "--range-max"}};
    CHECK(name_flags("Options::range_max 2 is below Options::range 3", flags) == "--range-max 2 is below --range 3");
    const FieldFlags driver{{"ApplyOptions::driver_path", "--driver"}};
    CHECK(name_flags("pass ApplyOptions::driver_path PATH to give its location", driver) ==
          "pass --driver PATH to give its location");
    CHECK(name_flags("using it as ApplyOptions::driver_path asks", driver) == "using it as --driver asks");
}
