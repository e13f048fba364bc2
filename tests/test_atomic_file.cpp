#include "fv/atomic_file.hpp"

#include <catch2/catch.hpp>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>

namespace {
std::string slurp(const std::string& p) {
    std::ifstream f(p);
    std::stringstream ss;
    ss << f.rdbuf();
    return ss.str();
}
std::string temp_dir() {
    char tmpl[] = "/tmp/fv-test-XXXXXX";
    return ::mkdtemp(tmpl);
}
} // namespace

TEST_CASE("write_file_atomic replaces the file whole and leaves no temporary behind", "[io]") {
    const std::string dir = temp_dir(), path = dir + "/out.csv";
    REQUIRE(fv::write_file_atomic(path, "first\n").empty());
    REQUIRE(fv::write_file_atomic(path, "second\n").empty());
    CHECK(slurp(path) == "second\n");
    CHECK(std::system(("test $(ls -A " + dir + " | wc -l) -eq 1").c_str()) == 0);
    std::system(("rm -rf " + dir).c_str());
}

TEST_CASE("Bad targets are refused before anything is written", "[io]") {
    const std::string dir = temp_dir();
    CHECK_FALSE(fv::check_writable(dir + "/missing/out.csv").empty());
    CHECK_FALSE(fv::check_writable(dir).empty()); // a directory
    CHECK_FALSE(fv::check_writable("").empty());
    CHECK_FALSE(fv::check_writable("/proc/out.csv").empty());
    CHECK(fv::check_writable(dir + "/fine.csv").empty());
    CHECK_FALSE(fv::write_file_atomic(dir + "/missing/out.csv", "x").empty());
    std::system(("rm -rf " + dir).c_str());
}
