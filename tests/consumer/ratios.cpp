// r_x through the installed frictionviz::core against results computed here, independently of the library:
// the rigid model's closed forms, Eq. (10) (theta = 0) and Eq. (11) (theta = 90 deg, with the standard
// library's complete elliptic integral, where the library uses the arithmetic-geometric mean), and a limit of
// the Dahl model: at theta = 0 and zeta > 1 the body point never moves backwards, the asperity stays fully
// deflected and r_x = 1 exactly. Exit status 0 when every value agrees, 1 otherwise.
#include <fv/params.hpp>
#include <fv/steady_state.hpp>

#include <cmath>
#include <cstdio>
#include <utility>

namespace {

int failures = 0;

void check(const char* what, double zeta, const fv::SteadyResult& r, double expected, double tolerance) {
    const bool good = fv::ok(r.status) && std::abs(r.rx - expected) <= tolerance;
    std::printf("%-31s zeta = %-5g r_x = %.12f expected %.12f status %s%s\n", what, zeta, r.rx, expected,
                fv::status_word(r).c_str(), good ? "" : "  <-- FAILED");
    if (!good) ++failures;
}

} // namespace

int main() {
    const double pi = std::acos(-1.0);
    fv::Params p;
    // Rigid model, theta = 0: Eq. (10), r_x = (2/pi) asin(zeta) up to zeta = 1, then 1.
    p.theta = 0;
    for (double zeta : {0.2, 0.6, 0.95, 1.5}) {
        p.zeta = zeta;
        const double eq10 = zeta <= 1 ? 2 / pi * std::asin(zeta) : 1.0;
        check("rigid, theta = 0, Eq. (10)", zeta, fv::steady_ratio(fv::Model::rigid, p), eq10, 1e-10);
    }
    // Rigid model, theta = 90 deg: Eq. (11), r_x = (2/pi) zeta / sqrt(1 + zeta^2) K(m), m = 1/(1 + zeta^2);
    // std::comp_ellint_1 takes the modulus k = sqrt(m).
    p.theta = pi / 2;
    for (double zeta : {0.1, 0.5, 2.0}) {
        p.zeta = zeta;
        const double k = 1 / std::sqrt(1 + zeta * zeta);
        const double eq11 = 2 / pi * zeta / std::sqrt(1 + zeta * zeta) * std::comp_ellint_1(k);
        check("rigid, theta = 90 deg, Eq. (11)", zeta, fv::steady_ratio(fv::Model::rigid, p), eq11, 1e-10);
    }
    // Dahl model, theta = 0, zeta > 1: r_x = 1 for any r_disp and i, within the solver's error estimate.
    p.theta = 0;
    p.zeta = 1.5;
    p.rdisp = 3;
    for (const auto& [i, label] : {std::pair{0.0, "Dahl i = 0, theta = 0"},
                                   {1.0, "Dahl i = 1, theta = 0"},
                                   {2.5, "Dahl i = 2.5, theta = 0"}}) {
        p.i = i;
        const fv::SteadyResult r = fv::steady_ratio(fv::Model::dahl, p);
        check(label, p.zeta, r, 1.0, fv::kErrorSafety * r.error_estimate + 1e-12);
    }
    // Parameters out of range are named, not computed.
    fv::Params bad;
    bad.zeta = -1;
    if (fv::validate(bad).empty()) {
        std::printf("validate() accepted zeta = -1  <-- FAILED\n");
        ++failures;
    }
    std::printf("%d failure(s)\n", failures);
    return failures == 0 ? 0 : 1;
}
