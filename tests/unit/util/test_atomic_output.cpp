// SPDX-License-Identifier: Apache-2.0
// AtomicOutput's temporaries: their names (checked against gethostname() and
// getpid(), and against names written out by hand), and which leftovers
// begin() removes: a dead process's (a child that has exited), never a live
// one's (this process, a child still running), never a file that is not the
// destination's temporary, another host's only once it is over a day old.
#include "cmfilter/util/atomic_output.h"
#include "cmfilter/util/stale_temporary_outputs.h"
#include "cmfilter/util/temporary_output_name.h"

#include <doctest/doctest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <set>
#include <string>

using namespace cmfilter;
namespace fs = std::filesystem;

namespace {

// A fresh, empty folder, removed with what it holds at the end.
class ScratchFolder {
public:
    ScratchFolder()
    {
        std::string pattern = (fs::temp_directory_path() / "cmfilter-atomic-XXXXXX").string();
        REQUIRE(mkdtemp(pattern.data()) != nullptr);
        path_ = pattern;
    }
    ~ScratchFolder()
    {
        std::error_code ec;
        fs::remove_all(path_, ec);
    }
    const fs::path& path() const { return path_; }

private:
    fs::path path_;
};

// The host name as gethostname() gives it; empty when there is none or it
// holds characters a temporary's name writes otherwise.
std::string plain_host_name()
{
    char buffer[256] = {};
    if (gethostname(buffer, sizeof buffer - 1) != 0) return {};
    const std::string host(buffer);
    if (host.empty() || !std::regex_match(host, std::regex("[A-Za-z0-9._-]+"))) return {};
    return host;
}

// The tests that write this host's name into names themselves are skipped
// where it is not plain.
const bool kHostNameNotPlain = plain_host_name().empty();

// A temporary's name written out here: ".<stem>.tmp-<host>-<pid>-<16 hex><ext>".
std::string temporary_name(const std::string& stem, const std::string& host, long pid, const std::string& ext)
{
    return "." + stem + ".tmp-" + host + "-" + std::to_string(pid) + "-0123456789abcdef" + ext;
}

void touch(const fs::path& path, const std::string& text = "partial")
{
    std::ofstream f(path, std::ios::binary);
    f << text;
    REQUIRE(f);
}

std::set<std::string> names_in(const fs::path& dir)
{
    std::set<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir)) names.insert(entry.path().filename().string());
    return names;
}

std::string read_all(const fs::path& path)
{
    std::ifstream f(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

// The id of a process that existed and is gone: a child that exited and was
// reaped.
pid_t dead_pid()
{
    const pid_t child = fork();
    REQUIRE(child >= 0);
    if (child == 0) _exit(0);
    int status = 0;
    REQUIRE(waitpid(child, &status, 0) == child);
    REQUIRE(kill(child, 0) == -1);
    REQUIRE(errno == ESRCH);
    return child;
}

// A child that runs until killed (waiting for a signal).
class LiveChild {
public:
    LiveChild()
    {
        pid_ = fork();
        REQUIRE(pid_ >= 0);
        if (pid_ == 0) {
            for (;;) pause();
        }
    }
    ~LiveChild() { stop(); }
    pid_t pid() const { return pid_; }
    void stop()
    {
        if (pid_ <= 0) return;
        kill(pid_, SIGKILL);
        int status = 0;
        waitpid(pid_, &status, 0);
        pid_ = 0;
    }

private:
    pid_t pid_ = 0;
};

}  // namespace

TEST_CASE("atomic output: the temporary is .<stem>.tmp-<host>-<pid>-<16 hex><ext> beside the destination" *
          doctest::skip(kHostNameNotPlain))
{
    const std::string host = plain_host_name();
    ScratchFolder dir;
    auto out = AtomicOutput::begin((dir.path() / "render.final.exr").string());
    REQUIRE(out);
    const fs::path temp(out->temp_path());
    CHECK(temp.parent_path() == dir.path());
    const std::string expected = "\\.render\\.final\\.tmp-" + std::regex_replace(host, std::regex("\\."), "\\.") + "-" +
                                 std::to_string(getpid()) + "-[0-9a-f]{16}\\.exr";
    CHECK_MESSAGE(std::regex_match(temp.filename().string(), std::regex(expected)), temp.filename().string());
    CHECK(temp.extension() == ".exr");
    CHECK_FALSE(fs::exists(temp));  // begin() creates nothing
}

TEST_CASE("atomic output: temporary names written by hand parse to their host and process, others do not")
{
    const auto parsed =
        parse_temporary_output_name(".render.tmp-farm-07.example-41234-3f9c0a17d2e4b586.exr", "render.exr");
    REQUIRE(parsed);
    CHECK(parsed->host == "farm-07.example");
    CHECK(parsed->pid == 41234);
    const auto folder = parse_temporary_output_name(".stack.tmp-h-9-0000000000000000", "stack");
    REQUIRE(folder);
    CHECK(folder->host == "h");
    CHECK(folder->pid == 9);
    for (const char* name : {
             ".render.tmp-3f9c0a17d2e4b586.exr",                   // the old name, without host and process
             ".render.tmp-farm-41234-3f9c0a17d2e4b586.png",        // another destination's extension
             ".other.tmp-farm-41234-3f9c0a17d2e4b586.exr",         // another destination's stem
             ".render.x.tmp-farm-41234-3f9c0a17d2e4b586.exr",      // the stem "render.x"
             "render.tmp-farm-41234-3f9c0a17d2e4b586.exr",         // no leading dot
             ".render.tmp-farm-41234-3f9c0a17d2e4b58.exr",         // 15 hex digits
             ".render.tmp-farm-41234-3F9C0A17D2E4B586.exr",        // upper-case hex
             ".render.tmp-farm-0-3f9c0a17d2e4b586.exr",            // process 0
             ".render.tmp-farm-4x234-3f9c0a17d2e4b586.exr",        // not a number
             ".render.tmp--41234-3f9c0a17d2e4b586.exr",            // no host
             ".render.tmp-far/m-41234-3f9c0a17d2e4b586.exr",       // not a host name
             ".render.tmp-farm-99999999999-3f9c0a17d2e4b586.exr",  // beyond any process id
             "render.exr",
         })
        CHECK_MESSAGE(!parse_temporary_output_name(name, "render.exr"), name);
}

TEST_CASE("atomic output: commit puts the whole file in place, or fails leaving the old one, and no temporary")
{
    ScratchFolder dir;
    const fs::path destination = dir.path() / "table.exr";
    touch(destination, "previous");
    auto out = AtomicOutput::begin(destination.string());
    REQUIRE(out);
    SUBCASE("a written temporary")
    {
        touch(out->temp_path(), "the new contents");
        CHECK(read_all(destination) == "previous");  // untouched until commit
        REQUIRE(out->commit());
        CHECK(read_all(destination) == "the new contents");
    }
    SUBCASE("a temporary that cannot be synced: it was never written, there is nothing to open")
    {
        const auto committed = out->commit();
        REQUIRE_FALSE(committed);
        CHECK(committed.error().kind == ErrorKind::Io);
        CHECK(committed.error().message.find("'" + destination.string() + "'") != std::string::npos);
        CHECK(committed.error().message.find("sync") != std::string::npos);
        CHECK(read_all(destination) == "previous");
    }
    CHECK(names_in(dir.path()) == std::set<std::string>{"table.exr"});
}

TEST_CASE("atomic output: an output without commit leaves nothing, not even its temporary")
{
    ScratchFolder dir;
    {
        auto out = AtomicOutput::begin((dir.path() / "table.exr").string());
        REQUIRE(out);
        touch(out->temp_path());
    }
    CHECK(names_in(dir.path()).empty());
}

TEST_CASE("atomic output: begin refuses a directory that is a file, naming both")
{
    ScratchFolder dir;
    touch(dir.path() / "plain");
    const std::string destination = (dir.path() / "plain" / "table.exr").string();
    auto out = AtomicOutput::begin(destination);
    REQUIRE_FALSE(out);
    CHECK(out.error().kind == ErrorKind::Io);
    CHECK(out.error().message.find("'" + destination + "'") != std::string::npos);
    CHECK(out.error().message.find("is not a directory") != std::string::npos);
}

TEST_CASE("atomic output: begin removes the temporary of a writer on this host whose process is gone" *
          doctest::skip(kHostNameNotPlain))
{
    const std::string host = plain_host_name();
    ScratchFolder dir;
    const std::string stale = temporary_name("render", host, dead_pid(), ".exr");
    touch(dir.path() / stale);
    auto out = AtomicOutput::begin((dir.path() / "render.exr").string());
    REQUIRE(out);
    CHECK(names_in(dir.path()).empty());
}

TEST_CASE("atomic output: begin keeps the temporaries of live writers on this host" * doctest::skip(kHostNameNotPlain))
{
    const std::string host = plain_host_name();
    ScratchFolder dir;
    LiveChild child;
    const std::string mine = temporary_name("render", host, getpid(), ".exr");
    const std::string childs = temporary_name("render", host, child.pid(), ".exr");
    touch(dir.path() / mine);
    touch(dir.path() / childs);
    REQUIRE(AtomicOutput::begin((dir.path() / "render.exr").string()));
    CHECK(names_in(dir.path()) == std::set<std::string>{mine, childs});
    // Once the child is gone its temporary is stale; this process's is not.
    child.stop();
    REQUIRE(AtomicOutput::begin((dir.path() / "render.exr").string()));
    CHECK(names_in(dir.path()) == std::set<std::string>{mine});
}

TEST_CASE("atomic output: begin keeps files that are not the destination's temporaries" *
          doctest::skip(kHostNameNotPlain))
{
    const std::string host = plain_host_name();
    ScratchFolder dir;
    const long gone = dead_pid();
    const std::set<std::string> kept = {
        "render.exr",
        ".render.tmp-3f9c0a17d2e4b586.exr",                      // the old name
        temporary_name("render", host, gone, ".png"),            // another destination
        temporary_name("other", host, gone, ".exr"),             // another destination
        temporary_name("render", host, gone, ".exr.bak"),        // not the pattern
        temporary_name("render", host, gone, ".exr").substr(1),  // no leading dot
    };
    for (const std::string& name : kept) touch(dir.path() / name);
    REQUIRE(AtomicOutput::begin((dir.path() / "render.exr").string()));
    CHECK(names_in(dir.path()) == kept);
}

TEST_CASE("atomic output: another host's temporary is removed once it is over 24 hours old, not before")
{
    ScratchFolder dir;
    const fs::path recent = dir.path() / temporary_name("render", "elsewhere.invalid", 123, ".exr");
    const fs::path old = dir.path() / temporary_name("render", "elsewhere.invalid", 124, ".exr");
    const fs::path day = dir.path() / temporary_name("render", "elsewhere.invalid", 125, ".exr");
    touch(recent);
    touch(old);
    touch(day);
    const auto now = fs::file_time_type::clock::now();
    fs::last_write_time(old, now - std::chrono::hours(25));
    fs::last_write_time(day, now - std::chrono::hours(23));
    REQUIRE(AtomicOutput::begin((dir.path() / "render.exr").string()));
    CHECK(names_in(dir.path()) == std::set<std::string>{recent.filename().string(), day.filename().string()});
}

TEST_CASE("atomic output: a dead writer's staging folder is removed with what it holds, a live one's kept" *
          doctest::skip(kHostNameNotPlain))
{
    const std::string host = plain_host_name();
    ScratchFolder dir;
    const fs::path dead = dir.path() / temporary_name("stack", host, dead_pid(), "");
    const fs::path live = dir.path() / temporary_name("stack", host, getpid(), "");
    for (const fs::path& folder : {dead, live}) {
        fs::create_directories(folder / "view-00");
        touch(folder / "view-00" / "stack-000.exr");
    }
    StaleTemporaryOptions options;
    options.destination = (dir.path() / "stack").string();
    const auto removed = remove_stale_temporary_outputs(options);
    REQUIRE(removed);
    CHECK(*removed == std::vector<std::string>{dead.string()});
    CHECK(names_in(dir.path()) == std::set<std::string>{live.filename().string()});
}

TEST_CASE("atomic output: a process is alive while it runs and not once it is reaped")
{
    CHECK(process_is_alive(getpid()));
    LiveChild child;
    const pid_t pid = child.pid();
    CHECK(process_is_alive(pid));
    child.stop();
    CHECK_FALSE(process_is_alive(pid));
    CHECK_FALSE(process_is_alive(0));
    CHECK_FALSE(process_is_alive(-1));
}
