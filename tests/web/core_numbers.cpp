// The model's numbers at a fixed set of points across the domain, for the browser build's test: the same
// source is built natively and with emcc (run under node), and the two must agree.
//   fv_core_numbers                 prints one line per point: model theta_deg rdisp i zeta r_x r_y status
//   fv_core_numbers --compare FILE  computes the same points and compares them with FILE (another build's
//                                   output): same points, same status, |r_x|, |r_y| differences <= 1e-12.
//                                   Exit 0 when all agree, 1 otherwise (each disagreement named).
#include "fv/params.hpp"
#include "fv/steady_state.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace {

struct Point {
    fv::Model model;
    double theta_deg, rdisp, i, zeta;
};

std::vector<Point> points() {
    std::vector<Point> out;
    // Rigid: Eq. (9) by quadrature, over the whole zeta range and the angles of the paper and beyond.
    for (double theta : {0.0, 15.0, 45.0, 60.0, 90.0, 120.0, 180.0})
        for (double zeta : {0.0, 0.01, 0.1, 0.3, 0.7, 1.0, 1.5, 3.0, 10.0, 100.0})
            out.push_back({fv::Model::rigid, theta, 0, 0, zeta});
    // Dahl: stiff and soft asperities, stick/slip (i = 0), the paper's i = 1 and a fractional exponent.
    for (double i : {0.0, 1.0, 2.5})
        for (double rdisp : {0.2, 2.0, 20.0, 1000.0})
            for (double theta : {0.0, 30.0, 90.0, 150.0})
                for (double zeta : {0.02, 0.15, 0.5, 0.9, 2.0})
                    out.push_back({fv::Model::dahl, theta, rdisp, i, zeta});
    return out;
}

std::string line(const Point& p) {
    const fv::Params params{p.zeta, p.theta_deg * fv::kPi / 180, p.model == fv::Model::rigid ? 2.0 : p.rdisp,
                            p.i};
    const fv::SteadyResult r = fv::steady_ratio(p.model, params);
    char buf[256];
    std::snprintf(buf, sizeof buf, "%s %.17g %.17g %.17g %.17g %.17g %.17g %s", fv::to_string(p.model),
                  p.theta_deg, p.rdisp, p.i, p.zeta, r.rx, r.ry, fv::to_string(r.status));
    return buf;
}

int compare(const char* file) {
    std::ifstream in(file);
    if (!in) {
        std::cerr << "cannot read " << file << "\n";
        return 1;
    }
    constexpr double kTolerance = 1e-12;
    int failed = 0, passed = 0;
    double worst = 0;
    std::string theirs;
    for (const Point& p : points()) {
        const std::string mine = line(p);
        if (!std::getline(in, theirs)) {
            std::cerr << "missing in " << file << ": " << mine << "\n";
            ++failed;
            continue;
        }
        std::istringstream a(mine), b(theirs);
        std::string ma, mb, sa, sb;
        double ka[6], kb[6];
        a >> ma >> ka[0] >> ka[1] >> ka[2] >> ka[3] >> ka[4] >> ka[5] >> sa;
        b >> mb >> kb[0] >> kb[1] >> kb[2] >> kb[3] >> kb[4] >> kb[5] >> sb;
        bool same = b && ma == mb && sa == sb;
        for (int k = 0; same && k < 4; ++k) same = ka[k] == kb[k];
        for (int k = 4; same && k < 6; ++k) {
            const double d = std::fabs(ka[k] - kb[k]);
            worst = std::fmax(worst, d);
            same = d <= kTolerance;
        }
        if (same) {
            ++passed;
        } else {
            ++failed;
            std::cerr << "differs:\n  native " << mine << "\n  other  " << theirs << "\n";
        }
    }
    if (std::getline(in, theirs)) {
        std::cerr << "extra lines in " << file << " from: " << theirs << "\n";
        ++failed;
    }
    std::printf("largest |r_x|, |r_y| difference %.3g (tolerance %.0e)\n", worst, kTolerance);
    std::printf("%d passed, %d failed\n", passed, failed);
    return failed == 0 ? 0 : 1;
}

} // namespace

int main(int argc, char** argv) {
    if (argc == 3 && std::string(argv[1]) == "--compare") return compare(argv[2]);
    if (argc != 1) {
        std::cerr << "usage: fv_core_numbers [--compare FILE]\n";
        return 2;
    }
    for (const Point& p : points()) std::cout << line(p) << "\n";
    return 0;
}
