#version 330 core
// Signed-distance evaluation of the canvas primitives. Distances are in logical pixels; the
// coverage ramp is one framebuffer pixel wide (u_ratio = framebuffer pixels per logical pixel).
// KIND: 1 dashed segment, 2 marker, 3 triangle, 4 rectangle, 5 solid segment, 6 flat (full coverage: the
// inside of a large fill, where every other kind would give 1 too).
// The program is compiled once per primitive kind with "#define KIND n" inserted after #version:
// llvmpipe pays for every branch of a divergent if, so a single uber-shader made a full-screen
// rectangle cost 20+ ms.
#ifndef KIND
#define KIND 1
#endif
flat in vec4 v_a;
flat in vec4 v_b;
flat in vec4 v_c;
flat in vec4 v_d;
flat in vec4 v_col;
uniform float u_fb_height; // framebuffer height, to turn gl_FragCoord into a top-left origin
uniform float u_ratio;
out vec4 o_color;

const float BIG = 1e9;

float coverage(float d) { return clamp(0.5 - d * u_ratio, 0.0, 1.0); }

float sd_box(vec2 p, vec2 half_size) {
    vec2 d = abs(p) - half_size;
    return length(max(d, 0.0)) + min(max(d.x, d.y), 0.0);
}

// Signed distance to a triangle (negative inside), after Inigo Quilez.
float sd_triangle(vec2 p, vec2 p0, vec2 p1, vec2 p2) {
    vec2 e0 = p1 - p0, e1 = p2 - p1, e2 = p0 - p2;
    vec2 v0 = p - p0, v1 = p - p1, v2 = p - p2;
    vec2 q0 = v0 - e0 * clamp(dot(v0, e0) / dot(e0, e0), 0.0, 1.0);
    vec2 q1 = v1 - e1 * clamp(dot(v1, e1) / dot(e1, e1), 0.0, 1.0);
    vec2 q2 = v2 - e2 * clamp(dot(v2, e2) / dot(e2, e2), 0.0, 1.0);
    float s = sign(e0.x * e2.y - e0.y * e2.x);
    vec2 d = min(min(vec2(dot(q0, q0), s * (v0.x * e0.y - v0.y * e0.x)),
                     vec2(dot(q1, q1), s * (v1.x * e1.y - v1.y * e1.x))),
                 vec2(dot(q2, q2), s * (v2.x * e2.y - v2.y * e2.x)));
    return -sqrt(d.x) * sign(d.y);
}

// Distance from p to the core of segment [a,b]. End regions use length(p - end) so that two
// segments sharing a vertex compute bit-identical distances there.
float seg_dist(vec2 p, vec2 a, vec2 b) {
    vec2 ab = b - a;
    float len2 = dot(ab, ab);
    float t = len2 > 0.0 ? dot(p - a, ab) / len2 : 0.0;
    if (t <= 0.0) return length(p - a);
    if (t >= 1.0) return length(p - b);
    return abs(ab.x * (p.y - a.y) - ab.y * (p.x - a.x)) / sqrt(len2);
}

// Distance from p to the "on" parts of a dashed segment [a,b] whose start is at arc length s0.
// Dashes are the intervals [k*period, k*period + on] of arc length (period <= 0: solid).
float dash_dist(vec2 p, vec2 a, vec2 b, float s0, float on, float period) {
    if (period <= 0.0) return seg_dist(p, a, b);
    vec2 ab = b - a;
    float len = length(ab);
    if (len <= 0.0) return BIG;
    vec2 dir = ab / len;
    float x = dot(p - a, dir);
    float y = dot(p - a, vec2(-dir.y, dir.x));
    float s = s0 + x;                   // arc length of the projection
    float sc = s0 + clamp(x, 0.0, len); // ... clamped to the segment
    float k0 = floor(sc / period);
    float best = BIG;
    for (int i = -1; i <= 1; ++i) {
        float k = k0 + float(i);
        float lo = max(k * period, s0), hi = min(k * period + on, s0 + len);
        if (lo <= hi) best = min(best, max(max(lo - s, s - hi), 0.0));
    }
    return best >= BIG ? BIG : length(vec2(best, y));
}

// Which side of the joint J (between segments A->J and J->B) p lies on: > 0 means B's segment.
// The dividing line is the angle bisector, so each pixel near a joint is drawn by one segment only
// (no double blending of translucent lines, no gaps).
float joint_side(vec2 p, vec2 A, vec2 J, vec2 B) {
    vec2 d0 = normalize(J - A), d1 = normalize(B - J);
    vec2 n = d0 + d1;
    if (dot(n, n) < 1e-8) n = d0; // hairpin: the next segment owns what lies beyond the joint
    return dot(p - J, n);
}

float segment_alpha(vec2 p) {
    vec2 prev = v_a.xy, p0 = v_a.zw, p1 = v_b.xy, next = v_b.zw;
    float hw = v_c.x, s0 = v_c.y, on = v_c.z, period = v_c.w;
    bool has_prev = v_d.y > 0.5, has_next = v_d.z > 0.5;
    float reach = hw + 1.0 / u_ratio + 0.5; // beyond this nothing of a segment is visible
    float g_self = seg_dist(p, p0, p1);
    if (g_self > reach) discard;
    float g_next = has_next ? seg_dist(p, p1, next) : BIG;
    float g_prev = has_prev ? seg_dist(p, prev, p0) : BIG;
    if (g_next <= reach && joint_side(p, p0, p1, next) > 0.0) discard;
    if (g_prev <= reach && joint_side(p, prev, p0, p1) <= 0.0) discard;
    // The owner shades the union of its own and its neighbours' (dashed) cores.
#if KIND == 5
    float d = min(g_self, min(g_prev, g_next));
#else
    float d = dash_dist(p, p0, p1, s0, on, period);
    if (has_prev) d = min(d, dash_dist(p, prev, p0, s0 - length(p0 - prev), on, period));
    if (has_next) d = min(d, dash_dist(p, p1, next, s0 + length(p1 - p0), on, period));
#endif
    return coverage(d - hw);
}

float marker_alpha(vec2 p) {
    vec2 q = p - v_a.xy;
    float r = v_a.z, stroke_hw = v_a.w;
    float shape = v_b.x;
    bool filled = v_b.y > 0.5;
    float d;
    if (shape < 1.5) { // circle
        d = length(q) - r;
    } else if (shape < 2.5) { // square, same visual weight as the circle
        d = sd_box(q, vec2(r * 0.88));
    } else if (shape < 3.5) { // triangle pointing up, centred on its centroid
        d = sd_triangle(q, vec2(0.0, -1.25 * r), vec2(1.08 * r, 0.62 * r), vec2(-1.08 * r, 0.62 * r));
    } else if (shape < 4.5) { // diamond
        vec2 rq = vec2(q.x + q.y, q.y - q.x) * 0.70710678;
        d = sd_box(rq, vec2(r * 0.85));
    } else { // cross (5) or plus (6): two bars of half-thickness b.z
        vec2 rq = shape < 5.5 ? vec2(q.x + q.y, q.y - q.x) * 0.70710678 : q;
        float arm = shape < 5.5 ? r * 1.1 : r, t = v_b.z;
        d = min(sd_box(rq, vec2(arm, t)), sd_box(rq, vec2(t, arm)));
    }
    return filled ? coverage(d) : coverage(abs(d) - stroke_hw);
}

void main() {
    vec2 p = vec2(gl_FragCoord.x, u_fb_height - gl_FragCoord.y) / u_ratio;
#if KIND == 1 || KIND == 5 // dashed / solid segment
    float alpha = segment_alpha(p);
#elif KIND == 2
    float alpha = marker_alpha(p);
#elif KIND == 3
    float alpha = coverage(sd_triangle(p, v_a.xy, v_a.zw, v_b.xy));
#elif KIND == 6
    float alpha = 1.0;
#else
    vec2 c = 0.5 * (v_a.xy + v_a.zw), h = 0.5 * (v_a.zw - v_a.xy);
    float d = sd_box(p - c, h);
    float alpha = v_b.y > 0.5 ? coverage(d) : coverage(abs(d) - v_b.x);
#endif
    if (alpha <= 0.0) discard;
    o_color = vec4(v_col.rgb, v_col.a * alpha);
}
