#include "fv/measurements.hpp"

#include <catch2/catch.hpp>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <random>
#include <string>
#include <unistd.h>

using fv::DataError;
using fv::parse_measurements;

namespace {

// The error a text gives (fails the test if it parses).
DataError error_of(const std::string& text, const fv::ReadOptions& opt = {}) {
    try {
        parse_measurements(text, "m.csv", opt);
    } catch (const DataError& e) {
        return e;
    }
    FAIL("parsed without error: " << text);
    return DataError("", 0, 0, "");
}

} // namespace

TEST_CASE("measurements: columns in any order, trimmed, comments, blank lines, CRLF", "[measurements]") {
    const std::string text = "\xEF\xBB\xBF# synthetic\r\n"
                             "\r\n"
                             "  label , sigma,r_x ,\ttheta_deg, zeta \r\n"
                             "   # a comment after leading blanks\r\n"
                             "a, 0.01, 0.5, 90, 0.25\r\n"
                             "\t\r\n"
                             ",0.02,+0.75,0,1e-1\r\n";
    const fv::MeasurementSet s = parse_measurements(text, "m.csv");
    REQUIRE(s.points.size() == 2);
    CHECK(s.has_sigma);
    CHECK(s.has_theta);
    CHECK_FALSE(s.from_vb);
    CHECK(s.points[0].label == "a");
    CHECK(s.points[0].zeta == 0.25);
    CHECK(s.points[0].rx == 0.5);
    CHECK(*s.points[0].theta_deg == 90);
    CHECK(*s.points[0].sigma == 0.01);
    CHECK(s.points[0].line == 5);
    CHECK(s.points[1].label.empty());
    CHECK(s.points[1].zeta == 0.1);
    CHECK(s.points[1].rx == 0.75);
    CHECK(s.points[1].line == 7);
}

TEST_CASE("measurements: a vb column is converted with the amplitude and frequency", "[measurements]") {
    fv::ReadOptions opt;
    opt.amplitude_um = 0.7;
    opt.frequency_khz = 60;
    const fv::MeasurementSet s = parse_measurements("vb,r_x\n0.263893782901543,0.8\n", "m.csv", opt);
    REQUIRE(s.points.size() == 1);
    CHECK(s.from_vb);
    CHECK_FALSE(s.has_sigma);
    CHECK(s.points[0].zeta == Approx(1.0).epsilon(1e-14));
    CHECK_FALSE(s.points[0].theta_deg);
}

TEST_CASE("measurements: every malformed file names file, line and column", "[measurements]") {
    struct Case {
        std::string text;
        int line, column;
        const char* says;
    };
    const std::string big_row = "zeta,r_x\n" + std::string(5000, '1') + ",0.5\n";
    for (const Case& c : {
             Case{"", 1, 1, "no header"},
             Case{"# only a comment\n\n", 3, 1, "no header"},
             Case{"zeta,r_x\n", 2, 1, "no data rows"},
             Case{"zeta,r_x\n# nothing\n", 3, 1, "no data rows"},
             Case{"r_x\n0.5\n", 1, 1, "missing required column 'zeta' or 'vb'"},
             Case{"zeta, sigma\n0.5,0.1\n", 1, 1, "missing required column 'r_x'"},
             Case{"zeta,r_x,speed\n", 1, 10, "unknown column 'speed'; allowed: zeta, vb, r_x"},
             Case{"zeta,r_x,  zeta\n", 1, 12, "duplicate column 'zeta'"},
             Case{"zeta,,r_x\n", 1, 6, "empty column name"},
             Case{"zeta,r_x,vb\n", 1, 10, "both 'zeta' and 'vb'"},
             Case{"r_x,vb\n", 1, 5, "needs the vibration amplitude"},
             Case{"zeta,r_x\n0.1,0.5\n0.2\n", 3, 4, "1 fields, but the header has 2"},
             Case{"zeta,r_x\n0.1,0.5,7\n", 2, 8, "3 fields, but the header has 2"},
             Case{"zeta,r_x\n0.1, abc\n", 2, 6,
                  "r_x = 'abc' is not a decimal number; allowed: r_x in [-0.5, 1.5]"},
             Case{"zeta,r_x\n0.1,0.5x\n", 2, 5, "is not a decimal number"},
             Case{"zeta,r_x\n0.1,\n", 2, 5, "r_x is empty; allowed: r_x in [-0.5, 1.5]"},
             Case{"zeta,r_x\n nan,0.5\n", 2, 2, "zeta = 'nan' is not a decimal number"},
             Case{"zeta,r_x\n0.1,inf\n", 2, 5, "r_x = 'inf' is not a decimal number"},
             Case{"zeta,r_x\n0.1,-infinity\n", 2, 5, "is not a decimal number"},
             Case{"zeta,r_x\n1e999,0.5\n", 2, 1,
                  "zeta = 1e999 is out of range (beyond double precision); allowed: zeta in [0, 100]"},
             Case{"zeta,r_x\n-0.1,0.5\n", 2, 1, "zeta = -0.1 is out of range; allowed: zeta in [0, 100]"},
             Case{"zeta,r_x\n100.5,0.5\n", 2, 1, "out of range"},
             Case{"zeta,r_x\n0.1,50\n", 2, 5, "r_x = 50 is out of range; allowed: r_x in [-0.5, 1.5]"},
             Case{"zeta,r_x\n0.1,-0.6\n", 2, 5, "out of range"},
             Case{"zeta,r_x,theta_deg\n0.1,0.5,181\n", 2, 9, "theta_deg = 181 is out of range"},
             Case{"zeta,r_x,sigma\n0.1,0.5,0\n", 2, 9,
                  "sigma = 0 is out of range; allowed: sigma in [1e-06, 10]"},
             Case{"zeta,r_x,sigma\n0.1,0.5,-1\n", 2, 9, "out of range"},
             Case{"zeta,r_x\r\n0.1,0.5\r\n0.2,0x1\r\n", 3, 5, "not a decimal number"},
             Case{"zeta,r_x\n0.1,0.5\n0.2,0.\x01\n", 3, 5, "'0.\\x01' is not a decimal number"},
             Case{std::string("zeta,r_x\n0.1,0\0.5\n", 18), 2, 6, "NUL byte"},
             Case{big_row, 2, 4097, "line longer than 4096 bytes"},
             Case{"\x89PNG\r\n\x1a\n\0\0\0\rIHDR", 1, 1, "unknown column '\\x89PNG'"},
         }) {
        INFO(c.text);
        const DataError e = error_of(c.text);
        CHECK(e.file == "m.csv");
        CHECK(e.line == c.line);
        CHECK(e.column == c.column);
        CHECK_THAT(e.message, Catch::Contains(c.says));
        CHECK(std::string(e.what()) ==
              "m.csv:" + std::to_string(c.line) + ":" + std::to_string(c.column) + ": " + e.message);
        CHECK(e.message.find('\n') == std::string::npos);
    }
}

TEST_CASE("measurements: row and size limits, bad conversion constants", "[measurements]") {
    fv::ReadOptions opt;
    opt.max_rows = 3;
    DataError e = error_of("zeta,r_x\n0,0\n0,0\n# c\n0,0\n0,0\n", opt);
    CHECK(e.line == 6);
    CHECK_THAT(e.message, Catch::Contains("more than 3 data rows"));

    fv::ReadOptions small;
    small.max_file_bytes = 20;
    e = error_of("zeta,r_x\n0.1,0.5\n0.2,0.6\n", small);
    CHECK(e.line == 3);
    CHECK(e.column == 4); // byte 21, the first past the limit
    CHECK_THAT(e.message, Catch::Contains("file larger than 20 bytes"));

    fv::ReadOptions units;
    units.amplitude_um = 0;
    units.frequency_khz = 60;
    e = error_of("r_x,vb\n0.5,0.1\n", units);
    CHECK(e.line == 1);
    CHECK(e.column == 5);
    CHECK_THAT(e.message, Catch::Contains("amplitude"));
    units.amplitude_um = 0.7;
    e = error_of("r_x,vb\n0.5,100\n", units); // zeta = 379
    CHECK(e.line == 2);
    CHECK_THAT(e.message, Catch::Contains("allowed: zeta in [0, 100]"));

    // Found by fuzzing: v_v = 2 pi f A underflowed to 0, so vb = 0 gave zeta = NaN and the row was accepted.
    units.amplitude_um = 1e-300;
    units.frequency_khz = 1e-300;
    e = error_of("vb,r_x\n0,0.06\n", units);
    CHECK(e.line == 1);
    CHECK(e.column == 1);
    CHECK_THAT(e.message, Catch::Contains("column 'vb' cannot be converted"));
    // v_v representable but vb / v_v beyond the doubles: out of the zeta range, not infinity or NaN.
    units.amplitude_um = 1e-150;
    units.frequency_khz = 1e-150;
    e = error_of("vb,r_x\n1e5,0.06\n", units);
    CHECK(e.line == 2);
    CHECK_THAT(e.message, Catch::Contains("allowed: zeta in [0, 100]"));
}

TEST_CASE("measurements: files, missing files and directories", "[measurements]") {
    char tmpl[] = "/tmp/fv-meas-XXXXXX";
    const std::string dir = ::mkdtemp(tmpl);
    const std::string path = dir + "/d.csv";
    std::ofstream(path) << "zeta,r_x\n0.5,0.4\n";
    CHECK(fv::read_measurements(path).points.size() == 1);
    CHECK_THROWS_WITH(fv::read_measurements(dir + "/none.csv"),
                      Catch::StartsWith(dir + "/none.csv: ") && Catch::Contains("does not exist"));
    CHECK_THROWS_WITH(fv::read_measurements(dir), Catch::Contains("is a directory"));
    std::remove(path.c_str());
    ::rmdir(dir.c_str());
}

TEST_CASE("measurements: random bytes never crash and only throw DataError", "[measurements][fuzz]") {
    std::mt19937 rng(12345);
    static const char kChars[] = "zeta,r_x,vb,theta_deg,sigma,label\n\r#\t -+.e0123456789nainf\0\xff";
    const std::string alphabet(kChars, sizeof kChars - 1);
    fv::ReadOptions opt;
    opt.amplitude_um = 0.7;
    opt.frequency_khz = 60;
    int parsed = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        std::string text;
        const bool structured = trial % 2 == 0;
        if (structured)
            text = trial % 4 == 0 ? "zeta,r_x,sigma,label\n0.25,0.5,0.01,a\n"
                                  : "vb , r_x,theta_deg\n0.05, 0.5, 45\n";
        // Every fifth structured file is left valid, so the happy path is exercised too.
        const int n = structured && trial % 5 == 0 ? 0 : static_cast<int>(rng() % 200);
        for (int k = 0; k < n; ++k)
            text += trial % 3 == 0 ? static_cast<char>(rng() % 256) : alphabet[rng() % alphabet.size()];
        try {
            parsed += !parse_measurements(text, "f.csv", opt).points.empty();
        } catch (const DataError& e) {
            CHECK(e.line >= 1);
            CHECK(e.column >= 1);
            CHECK(e.message.find('\n') == std::string::npos);
        }
    }
    CHECK(parsed >= 300);
}
