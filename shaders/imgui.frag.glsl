#version 330 core
// SOLID: the ImGui renderer's program for large runs of untextured triangles (window and frame backgrounds):
// their UVs all point at the atlas' white texel, which samples to exactly 1, so v_col alone gives the same
// pixels without llvmpipe's per-pixel texture fetch (about half the cost of the app's panels).
in vec2 v_uv;
in vec4 v_col;
uniform sampler2D u_tex;
out vec4 o_color;
#ifdef SOLID
void main() { o_color = v_col; }
#else
void main() { o_color = v_col * texture(u_tex, v_uv); }
#endif
