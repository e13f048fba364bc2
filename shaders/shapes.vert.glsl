#version 330 core
// One vertex of a primitive's bounding quad. The shape itself is described by flat parameters
// (a, b, c, d) and evaluated per fragment as a signed distance, which gives exact antialiasing.
layout(location = 0) in vec2 a_pos; // logical pixels, top-left origin
layout(location = 1) in vec4 a_a;
layout(location = 2) in vec4 a_b;
layout(location = 3) in vec4 a_c;
layout(location = 4) in vec4 a_d;   // d.x = primitive kind
layout(location = 5) in vec4 a_col; // RGBA8, normalised
uniform vec2 u_size;                // logical canvas size
flat out vec4 v_a;
flat out vec4 v_b;
flat out vec4 v_c;
flat out vec4 v_d;
flat out vec4 v_col;
void main() {
    v_a = a_a;
    v_b = a_b;
    v_c = a_c;
    v_d = a_d;
    v_col = a_col;
    gl_Position = vec4(2.0 * a_pos.x / u_size.x - 1.0, 1.0 - 2.0 * a_pos.y / u_size.y, 0.0, 1.0);
}
