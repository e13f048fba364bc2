// One step of the 3-stage Radau IIA method (order 5, L-stable, stiffly accurate) for a small system
// y' = f(tau, y) of dimension N (1 or 2 here), with
//   - the stage equations solved by simplified Newton (the analytic Jacobian at the step's start),
//   - Hairer's error estimate (Hairer & Wanner, Solving ODEs II, Sec. IV.8, as in RADAU5),
//   - the collocation polynomial as dense output (order 3 between the nodes, exact at them),
//   - the derivative of the step map dy1/dy0 (the discrete variational equation), computed at the converged
//     stages: the sensitivity of the numerical period map, so that Newton on that map converges to its own
//     fixed point quadratically.
// The integrator knows nothing about friction: a problem supplies f, its Jacobian and the force to integrate.
#pragma once

#include <Eigen/Core>
#include <Eigen/LU> // the Hermite weights, once

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>

namespace fv::solver {

struct RadauTableau {
    static constexpr double s6 = 2.449489742783178098197284; // sqrt(6)
    static constexpr double c1 = (4 - s6) / 10, c2 = (4 + s6) / 10;
    static constexpr double a11 = (88 - 7 * s6) / 360, a12 = (296 - 169 * s6) / 1800,
                            a13 = (-2 + 3 * s6) / 225;
    static constexpr double a21 = (296 + 169 * s6) / 1800, a22 = (88 + 7 * s6) / 360,
                            a23 = (-2 - 3 * s6) / 225;
    static constexpr double a31 = (16 - s6) / 36, a32 = (16 + s6) / 36, a33 = 1.0 / 9;
    // Error estimator (RADAU5): err = (u1/h I - J)^-1 (f(y0) + (dd1 Z1 + dd2 Z2 + dd3 Z3)/h).
    static constexpr double dd1 = -(13 + 7 * s6) / 3, dd2 = (-13 + 7 * s6) / 3, dd3 = -1.0 / 3;
    // u1 = 1 / gamma, gamma the real eigenvalue of A: 30 / (6 + 81^(1/3) - 9^(1/3)).
    static constexpr double u1 = 30.0 / (6.0 + 4.3267487109222245 - 2.0800838230519041);
    // A^-1 = T diag(u1, [alpha -beta; beta alpha]) T^-1 (RADAU5's T and TI): the stage system splits into
    // one real and one complex system of the problem's size. alpha +- i beta are the complex eigenvalues
    // of A^-1: (12 - 81^(1/3) + 9^(1/3))/60 and (81^(1/3) + 9^(1/3)) sqrt(3)/60, divided by their modulus^2.
    static constexpr double alpha_raw = (12.0 - 4.3267487109222245 + 2.0800838230519041) / 60.0;
    static constexpr double beta_raw = (4.3267487109222245 + 2.0800838230519041) * 1.7320508075688772 / 60.0;
    static constexpr double alpha = alpha_raw / (alpha_raw * alpha_raw + beta_raw * beta_raw);
    static constexpr double beta = beta_raw / (alpha_raw * alpha_raw + beta_raw * beta_raw);
    static constexpr double t[3][3] = {
        {9.1232394870892942792e-02, -0.14125529502095420843, -3.0029194105147424492e-02},
        {0.24171793270710701896, 0.20412935229379993199, 0.38294211275726193779},
        {0.96604818261509293619, 1.0, 0.0}};
    static constexpr double ti[3][3] = {
        {4.3255798900631553510, 0.33919925181580986954, 0.54177053993587487119},
        {-4.1787185915519047273, -0.32768282076106238708, 0.47662355450055045196},
        {-0.50287263494578687595, 2.5719269498556054292, -0.59603920482822492497}};
};

// Gaussian elimination with partial pivoting for the small fixed-size systems here (1 to 6 unknowns; Eigen's
// PartialPivLU takes its general, blocked path for them, at several times the cost). The pivots' reciprocals
// are kept, so that a solve multiplies (a complex division is a library call).
template <class Scalar, int M> class SmallLU {
  public:
    using Mat = Eigen::Matrix<Scalar, M, M>;
    explicit SmallLU(const Mat& a) : lu_(a) {
        for (int k = 0; k < M; ++k) {
            int p = k;
            for (int i = k + 1; i < M; ++i)
                if (std::abs(lu_(i, k)) > std::abs(lu_(p, k))) p = i;
            perm_[k] = p;
            if (p != k) lu_.row(k).swap(lu_.row(p));
            inv_[k] = reciprocal(lu_(k, k));
            for (int i = k + 1; i < M; ++i) {
                const Scalar l = lu_(i, k) * inv_[k];
                lu_(i, k) = l;
                for (int j = k + 1; j < M; ++j) lu_(i, j) -= l * lu_(k, j);
            }
        }
    }
    // Solves for every column of b (M x K).
    template <class B> B solve(B b) const {
        for (int k = 0; k < M; ++k)
            if (perm_[k] != k) b.row(k).swap(b.row(perm_[k]));
        for (int k = 0; k < M; ++k)
            for (int i = k + 1; i < M; ++i) b.row(i) -= lu_(i, k) * b.row(k);
        for (int k = M - 1; k >= 0; --k) {
            for (int j = k + 1; j < M; ++j) b.row(k) -= lu_(k, j) * b.row(j);
            b.row(k) *= inv_[k];
        }
        return b;
    }

  private:
    static double reciprocal(double x) { return 1 / x; }
    // Without the library's scaling for extreme magnitudes (|x|^2 stays far inside the range here).
    static std::complex<double> reciprocal(const std::complex<double>& x) {
        return std::conj(x) / std::norm(x);
    }
    Mat lu_;
    int perm_[M];
    Scalar inv_[M];
};

// A problem supplies, for its dimension N (1 or 2 here):
//   Point eval(double tau, const Vec& y) const   the law at (tau, y): Point::f is the rate y', and the point
//                                                keeps what the Jacobian and the force need (so that each
//                                                stage costs one evaluation of the law);
//   Mat jac(const Point&) const                  dy'/dy there;
//   Vec2 force(const Point&), force(const Vec&)  the friction force F/F_c at a state;
//   Vec2 force_rate(const Point&)                dF/dtau along the law.
template <class Pb> struct RadauStep {
    static constexpr int N = Pb::N;
    using Vec = Eigen::Matrix<double, N, 1>;
    using Mat = Eigen::Matrix<double, N, N>;
    using Point = typename Pb::Point;

    double tau0 = 0, h = 0;
    Vec y0 = Vec::Zero();
    Vec z[3];            // stage increments Y_j - y0 at tau0 + c_j h (z[2] = y1 - y0: stiffly accurate)
    Point p0, pz[3];     // the law at the start and at the converged stages (pz[2]: at the step's end)
    Mat dy1_dy0_minus_i; // d y1 / d y0 - I
    double error = 0;    // scaled error norm (accept when <= 1)
    bool solved = false; // stage equations converged

    Vec y1() const { return y0 + z[2]; }
    // Collocation polynomial through (0, 0), (c1, z1), (c2, z2), (1, z3) at s = (tau - tau0)/h in [0, 1].
    Vec at(double s) const {
        using T = RadauTableau;
        const double l1 = s * (s - T::c2) * (s - 1) / (T::c1 * (T::c1 - T::c2) * (T::c1 - 1));
        const double l2 = s * (s - T::c1) * (s - 1) / (T::c2 * (T::c2 - T::c1) * (T::c2 - 1));
        const double l3 = s * (s - T::c1) * (s - T::c2) / ((1 - T::c1) * (1 - T::c2));
        return y0 + l1 * z[0] + l2 * z[1] + l3 * z[2];
    }
};

// Takes one step of size h from (tau0, y0), where the law is `start` (pb.eval(tau0, y0): the caller has it
// from the previous step's end or from a rejected try). `guess` (may be null) is a previous step whose
// collocation polynomial, extrapolated, starts the stage iteration. `atol` is the absolute tolerance per
// component (the problems are scaled so that their variables are O(1) displacements). `want_sensitivity`
// computes dy1/dy0.
template <class Pb>
RadauStep<Pb> radau_step(const Pb& pb, double tau0, const typename RadauStep<Pb>::Vec& y0,
                         const typename Pb::Point& start, double h, double atol, const RadauStep<Pb>* guess,
                         bool want_sensitivity, bool estimate_twice) {
    using T = RadauTableau;
    using S = RadauStep<Pb>;
    constexpr int N = S::N;
    using Vec = typename S::Vec;
    using Mat = typename S::Mat;
    static constexpr double A[3][3] = {
        {T::a11, T::a12, T::a13}, {T::a21, T::a22, T::a23}, {T::a31, T::a32, T::a33}};
    static constexpr double C[3] = {T::c1, T::c2, 1.0};

    S st;
    st.tau0 = tau0;
    st.h = h;
    st.y0 = y0;
    st.p0 = start;
    const Vec& f0 = st.p0.f;
    if (guess && guess->h > 0) {
        // Extrapolate the previous collocation polynomial to the new nodes.
        for (int j = 0; j < 3; ++j) {
            const double s = (tau0 + C[j] * h - guess->tau0) / guess->h;
            st.z[j] = guess->at(s) - y0;
        }
    } else {
        for (int j = 0; j < 3; ++j) st.z[j] = C[j] * h * f0;
    }
    const Mat J0 = pb.jac(st.p0);
    const double fac1 = T::u1 / h;
    Mat E1 = -J0;
    E1.diagonal().array() += fac1;
    const SmallLU<double, N> lu1(E1); // the error estimate's filter; the simplified Newton's real system
    const double stop = 1e-2 * atol;
    st.solved = false;
    // A stiff scalar law (the circle's angle where |h J| > kStiff): full Newton on the 3 stage equations
    //   G(Z) = Z - h A F(y0 + Z) = 0,  G' = I - h A diag(J_j),
    // with each stage's own Jacobian: a 3 x 3 solve costs little next to evaluating the law, and the
    // convergence is quadratic where the simplified iteration's rate, |h J| times the Jacobian's relative
    // change over the step, is slow (4 iterations per step at rdisp = 1e4), and its stopping rule leaves
    // stage errors that the force, r times the state, magnifies past the quadrature's tolerance (twice
    // the steps). Elsewhere the simplified iteration is cheaper per iteration and converges as fast.
    static constexpr double kStiff = 4;
    if (N == 1 && std::abs(h * J0(0, 0)) > kStiff) {
        // The law is evaluated once per iteration: at the iterate, which after a small enough correction
        // is the converged one.
        double prev_norm = 0;
        for (int it = 0; it < 10; ++it) {
            for (int j = 0; j < 3; ++j) st.pz[j] = pb.eval(tau0 + C[j] * h, Vec(y0 + st.z[j]));
            if (it >= 1 && prev_norm <= stop) {
                st.solved = true;
                break;
            }
            double js[3];
            for (int j = 0; j < 3; ++j) js[j] = pb.jac(st.pz[j])(0, 0);
            Eigen::Matrix3d M;
            Eigen::Vector3d res;
            for (int i = 0; i < 3; ++i) {
                res[i] = st.z[i][0];
                for (int j = 0; j < 3; ++j) {
                    const double hA = h * A[i][j];
                    res[i] -= hA * st.pz[j].f[0];
                    M(i, j) = (i == j ? 1.0 : 0.0) - hA * js[j];
                }
            }
            const Eigen::Vector3d dz = SmallLU<double, 3>(M).solve(Eigen::Vector3d(-res));
            if (!dz.allFinite()) break;
            for (int j = 0; j < 3; ++j) st.z[j][0] += dz[j];
            const double nrm = dz.cwiseAbs().maxCoeff();
            // A correction that does not shrink fast will not get there: the caller shortens the step.
            if (it >= 1 && nrm > 0.5 * prev_norm) break;
            prev_norm = nrm;
        }
    } else {
        // Simplified Newton with the Jacobian at the step's start, in RADAU5's transformed variables
        // W = (T^-1 x I) Z: the 3N x 3N system (I - h A x J0) dZ = -(Z - h (A x I) F) becomes
        //   (u1/h - J0) dW1 = (T^-1 F)_1 - u1/h W1                      (real, N x N),
        //   ((alpha + i beta)/h - J0) (dW2 + i dW3) = ... (complex, N x N),
        // the same iterates (Hairer & Wanner, Sec. IV.8).
        using Cplx = std::complex<double>;
        using CVec = Eigen::Matrix<Cplx, N, 1>;
        using CMat = Eigen::Matrix<Cplx, N, N>;
        const double alphn = T::alpha / h, betan = T::beta / h;
        CMat E2 = -J0.template cast<Cplx>();
        E2.diagonal().array() += Cplx(alphn, betan);
        const SmallLU<Cplx, N> lu2(E2);
        Vec w[3];
        for (int i = 0; i < 3; ++i)
            w[i] = T::ti[i][0] * st.z[0] + T::ti[i][1] * st.z[1] + T::ti[i][2] * st.z[2];
        double prev_norm = 0;
        for (int it = 0; it < 10; ++it) {
            for (int j = 0; j < 3; ++j) st.pz[j] = pb.eval(tau0 + C[j] * h, Vec(y0 + st.z[j]));
            Vec r[3];
            for (int i = 0; i < 3; ++i)
                r[i] = T::ti[i][0] * st.pz[0].f + T::ti[i][1] * st.pz[1].f + T::ti[i][2] * st.pz[2].f;
            r[0] -= fac1 * w[0];
            r[1] -= alphn * w[1] - betan * w[2];
            r[2] -= betan * w[1] + alphn * w[2];
            const Vec dw1 = lu1.solve(r[0]);
            const CVec dw23 =
                lu2.solve(CVec(r[1].template cast<Cplx>() + Cplx(0, 1) * r[2].template cast<Cplx>()));
            const Vec dw[3] = {dw1, dw23.real(), dw23.imag()};
            double nrm = 0;
            bool finite = true;
            for (int j = 0; j < 3; ++j) {
                w[j] += dw[j];
                const Vec dz = T::t[j][0] * dw[0] + T::t[j][1] * dw[1] + T::t[j][2] * dw[2];
                finite = finite && dz.allFinite();
                st.z[j] += dz;
                nrm = std::max(nrm, dz.cwiseAbs().maxCoeff());
            }
            if (!finite) break;
            // Done when what is left of the iteration is below `stop`: after this correction at most
            // theta / (1 - theta) of it, theta the observed contraction rate (RADAU5's rule); in the first
            // iteration, with no rate yet, the correction itself.
            const double theta = it >= 1 && prev_norm > 0 ? nrm / prev_norm : 1;
            const double left = theta < 0.9 ? nrm * theta / (1 - theta) : nrm;
            if (left <= stop) {
                st.solved = true;
                for (int j = 0; j < 3; ++j) st.pz[j] = pb.eval(tau0 + C[j] * h, Vec(y0 + st.z[j]));
                break;
            }
            // A contraction rate near 1 (or worse) will not get there: the caller shortens the step.
            if (it >= 1 && nrm > 0.9 * prev_norm) break;
            prev_norm = nrm;
        }
    }
    if (!st.solved) {
        st.error = std::numeric_limits<double>::infinity();
        return st;
    }
    // Error estimate (RADAU5's ESTRAD), filtered through (u1/h - J)^-1 so that it stays meaningful for
    // stiff components.
    const Vec f2 = (T::dd1 * st.z[0] + T::dd2 * st.z[1] + T::dd3 * st.z[2]) / h;
    Vec err = lu1.solve(Vec(f2 + f0));
    auto norm = [&](const Vec& e) { return e.cwiseAbs().maxCoeff() / atol; };
    st.error = norm(err);
    if (st.error >= 1 && estimate_twice) {
        err = lu1.solve(Vec(pb.eval(tau0, Vec(y0 + err)).f + f2));
        st.error = norm(err);
    }
    if (!std::isfinite(st.error)) st.error = std::numeric_limits<double>::infinity();
    if (want_sensitivity) {
        // Differentiate Z = h (A x I) F(y0 + Z) with respect to y0 at the converged stages:
        // (I - h (A x I) diag(J_j)) dZ = h (A x I) [J_1; J_2; J_3].
        Mat js[3];
        for (int j = 0; j < 3; ++j) js[j] = pb.jac(st.pz[j]);
        Eigen::Matrix<double, 3 * N, 3 * N> G;
        Eigen::Matrix<double, 3 * N, N> rhs;
        for (int i = 0; i < 3; ++i) {
            Mat b = Mat::Zero();
            for (int j = 0; j < 3; ++j) {
                G.template block<N, N>(N * i, N * j) =
                    (i == j ? Mat(Mat::Identity()) : Mat(Mat::Zero())) - h * A[i][j] * js[j];
                b += h * A[i][j] * js[j];
            }
            rhs.template block<N, N>(N * i, 0) = b;
        }
        const Eigen::Matrix<double, 3 * N, N> dZ = SmallLU<double, 3 * N>(G).solve(rhs);
        st.dy1_dy0_minus_i = dZ.template block<N, N>(2 * N, 0);
    } else {
        st.dy1_dy0_minus_i.setZero();
    }
    return st;
}

// Quadrature over a step from values g and derivatives g' of the integrand at the nodes {0, c1, c2, 1}
// (Hermite interpolation, exact for degree 7): h sum_k (w_k g_k + h v_k g'_k). Moments:
// sum_k w_k x_k^j + sum_k v_k j x_k^(j-1) = 1/(j+1), j = 0..7.
struct HermiteWeights {
    Eigen::Vector4d w, v;
};
inline const HermiteWeights& hermite_weights() {
    static const HermiteWeights hw = [] {
        using T = RadauTableau;
        const double x[4] = {0, T::c1, T::c2, 1};
        Eigen::Matrix<double, 8, 8> M;
        Eigen::Matrix<double, 8, 1> m;
        for (int j = 0; j < 8; ++j) {
            for (int k = 0; k < 4; ++k) {
                M(j, k) = j == 0 ? 1.0 : std::pow(x[k], j);
                M(j, 4 + k) = j == 0 ? 0.0 : j * (j == 1 ? 1.0 : std::pow(x[k], j - 1));
            }
            m[j] = 1.0 / (j + 1);
        }
        const Eigen::Matrix<double, 8, 1> sol = M.fullPivLu().solve(m);
        return HermiteWeights{sol.head<4>(), sol.tail<4>()};
    }();
    return hw;
}

// Integral of the force F over the step, from F and dF/dtau at the start and at the converged stages.
// Returns the Hermite rule (degree 7) and stores in `err` its difference from the Radau rule on the same
// values (degree 4): the latter's error estimate, and a bound for the former's. Needed because where the
// state is quasi-static (a stiff tip tracking the body), the state's local error is damped away while the
// integrand still varies: the state's error estimate alone lets the steps grow past what the quadrature of
// F can follow.
template <class Pb> Eigen::Vector2d step_integral(const Pb& pb, const RadauStep<Pb>& st, double& err) {
    using T = RadauTableau;
    const HermiteWeights& hw = hermite_weights();
    Eigen::Vector2d q(0, 0), qd(0, 0), q5(0, 0);
    const double b[4] = {0, T::a31, T::a32, T::a33};
    for (int k = 0; k < 4; ++k) {
        const typename Pb::Point& pt = k == 0 ? st.p0 : st.pz[k - 1];
        const Eigen::Vector2d gk = pb.force(pt);
        const Eigen::Vector2d dgk = pb.force_rate(pt);
        q += hw.w[k] * gk;
        qd += hw.v[k] * dgk;
        q5 += b[k] * gk;
    }
    const Eigen::Vector2d qh = st.h * (q + st.h * qd);
    err = (qh - st.h * q5).cwiseAbs().maxCoeff();
    return qh;
}

} // namespace fv::solver
