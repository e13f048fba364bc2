#include "fv/top_view_frame.hpp"

#include <algorithm>
#include <cmath>

namespace fv {

const char* to_string(FrameChoice f) {
    return f == FrameChoice::ground ? "ground" : "body";
}

std::optional<FrameChoice> parse_frame(const std::string& s) {
    if (s == "body") return FrameChoice::body;
    if (s == "ground") return FrameChoice::ground;
    return std::nullopt;
}

BodyOutline body_outline(Model model, const Params& p) {
    // Rigid: a block holding P's arrows (v scaled by 0.4, |v| <= 1 + zeta by Eq. (1); the friction 0.5 long),
    // so that v_b along its top edge meets none of them (a small block's edge crossed them).
    if (model == Model::rigid) {
        const double reach = std::max(0.5, 0.4 * (1 + p.zeta)) + 0.1;
        return {reach, reach};
    }
    return {1.15 * p.zss() + 0.25, 1.15 * p.zss() + 0.18};
}

FrameBox steady_frame(Model model, const Params& p, double trail_periods, double aspect) {
    const double cx = std::abs(std::cos(p.theta)), cy = std::abs(std::sin(p.theta));
    const bool dahl = model == Model::dahl;
    const double reach = dahl ? p.zss() : 0; // T's distance from P at most
    // P's segment C +- (cos theta, sin theta) and the trails it leaves at v_b = zeta (x_v per unit tau), T's
    // within `reach` of them: the last half period of them. Older parts, faded, may leave at the edge: a
    // frame holding a long trail at a large zeta would shrink the body and its arrows to a few pixels.
    const double drift = p.zeta * std::clamp(trail_periods, 0.0, kFrameTrailPeriods) * 2 * kPi;
    FrameBox b{-cx - drift - reach, cx + reach, -cy - reach, cy + reach};
    auto take = [&b](double x0, double x1, double y0, double y1) {
        b.x0 = std::min(b.x0, x0), b.x1 = std::max(b.x1, x1), b.y0 = std::min(b.y0, y0),
        b.y1 = std::max(b.y1, y1);
    };
    // The arrows at P: P + 0.4 v with v = (zeta, 0) + cos(tau) (cos theta, sin theta), Eq. (1): P + 0.4 v =
    // C + (sin tau + 0.4 cos tau) (cos theta, sin theta) + (0.4 zeta, 0), at most sqrt(1.16) along the line;
    // the friction P - 0.5 F/F_c, within 0.5 of P.
    const double a = std::sqrt(1.16);
    take(-a * cx, a * cx + 0.4 * p.zeta, -a * cy, a * cy);
    take(-cx - 0.5, cx + 0.5, -cy - 0.5, cy + 0.5);
    // The body's outline around P (it holds the z_ss circle and T), and its v_b arrow along the top edge,
    // unless the outline dwarfs the motion.
    const BodyOutline o = body_outline(model, p);
    if (std::max(o.half_w, o.half_h) <= 2 * std::max({b.width(), b.height(), 1.0}))
        take(-cx - o.half_w, std::max(cx + o.half_w, cx - o.half_w + 0.4 * p.zeta), -cy - o.half_h,
             cy + o.half_h);
    // A margin for the marks and the labels beyond the arrows' heads.
    const double m = 0.08 * std::max(b.width(), b.height());
    b.x0 -= m, b.x1 += m, b.y0 -= m, b.y1 += m;
    if (aspect > 0) {
        const double mx = 0.5 * (b.x0 + b.x1), my = 0.5 * (b.y0 + b.y1);
        const double w = std::max(b.width(), aspect * b.height()), h = w / aspect;
        b = {mx - 0.5 * w, mx + 0.5 * w, my - 0.5 * h, my + 0.5 * h};
    }
    return b;
}

FrameBox eased_frame(const FrameBox& from, const FrameBox& to, double s) {
    s = std::clamp(s, 0.0, 1.0);
    const double k = s * s * (3 - 2 * s); // smoothstep: monotone on [0, 1], flat at both ends
    auto mix = [k](double a, double b) { return k >= 1 ? b : a + k * (b - a); };
    return {mix(from.x0, to.x0), mix(from.x1, to.x1), mix(from.y0, to.y0), mix(from.y1, to.y1)};
}

} // namespace fv
