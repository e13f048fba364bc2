#include "fv/quadrature.hpp"

#include <algorithm>
#include <cmath>
#include <queue>

namespace fv {
namespace {

// 15-point Kronrod nodes and weights on [-1, 1] with the embedded 7-point Gauss rule (QUADPACK qk15).
constexpr double xgk[8] = {0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
                           0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
                           0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
                           0.207784955007898467600689403773245, 0.000000000000000000000000000000000};
constexpr double wgk[8] = {0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
                           0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
                           0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
                           0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
constexpr double wg[4] = {0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
                          0.381830050505118944950369775488975, 0.417959183673469387755102040816327};

struct Piece {
    double a, b, value, error;
    bool operator<(const Piece& o) const { return error < o.error; }
};

Piece kronrod15(const std::function<double(double)>& f, double a, double b) {
    const double c = 0.5 * (a + b), h = 0.5 * (b - a);
    const double fc = f(c);
    double k = fc * wgk[7], g = fc * wg[3];
    for (int j = 0; j < 7; ++j) {
        const double fs = f(c - h * xgk[j]) + f(c + h * xgk[j]);
        k += wgk[j] * fs;
        if (j % 2 == 1) g += wg[j / 2] * fs; // odd Kronrod nodes are the Gauss nodes
    }
    return {a, b, k * h, std::abs((k - g) * h)};
}

} // namespace

QuadResult integrate(const std::function<double(double)>& f, double a, double b, std::vector<double> breaks,
                     double abs_tol, int max_intervals) {
    breaks.erase(std::remove_if(breaks.begin(), breaks.end(), [&](double x) { return !(x > a && x < b); }),
                 breaks.end());
    std::sort(breaks.begin(), breaks.end());
    breaks.erase(std::unique(breaks.begin(), breaks.end()), breaks.end());
    std::vector<double> edges{a};
    edges.insert(edges.end(), breaks.begin(), breaks.end());
    edges.push_back(b);

    std::priority_queue<Piece> heap;
    QuadResult r;
    double value = 0, error = 0;
    for (std::size_t j = 0; j + 1 < edges.size(); ++j) {
        const Piece p = kronrod15(f, edges[j], edges[j + 1]);
        r.evaluations += 15;
        value += p.value;
        error += p.error;
        heap.push(p);
    }
    while (error > abs_tol && static_cast<int>(heap.size()) < max_intervals) {
        const Piece worst = heap.top();
        const double mid = 0.5 * (worst.a + worst.b);
        if (!(mid > worst.a && mid < worst.b)) break; // interval cannot be split further in double precision
        heap.pop();
        const Piece left = kronrod15(f, worst.a, mid), right = kronrod15(f, mid, worst.b);
        r.evaluations += 30;
        value += left.value + right.value - worst.value;
        error += left.error + right.error - worst.error;
        heap.push(left);
        heap.push(right);
    }
    // Re-sum to shed the rounding of the running updates.
    value = 0;
    error = 0;
    while (!heap.empty()) {
        value += heap.top().value;
        error += heap.top().error;
        heap.pop();
    }
    r.value = value;
    r.error = error;
    r.converged = error <= abs_tol;
    return r;
}

} // namespace fv
