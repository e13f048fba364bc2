#pragma once
// General renderer for Dear ImGui draw data on GL 3.3 core, through our GlApi table.
// (The prebuilt ImGui OpenGL3 backend resolves GL via libGL and fails under OSMesa.)
// Used for the app's ImGui panels and for the text the Canvas emits as ImDrawLists.
#include "fv/gfx/gl_api.hpp"
#include "fv/gfx/shader_program.hpp"

#include <vector>

struct ImDrawData;
struct ImDrawList;
struct ImDrawCmd;
struct ImFontAtlas;

namespace fv::gfx {

class ImGuiRenderer {
  public:
    explicit ImGuiRenderer(const GlApi& gl);
    ~ImGuiRenderer();
    ImGuiRenderer(const ImGuiRenderer&) = delete;
    ImGuiRenderer& operator=(const ImGuiRenderer&) = delete;

    /// Uploads the atlas' RGBA32 texture and stores its GL name as the atlas TexID.
    /// Call again after rebuilding the atlas. The renderer owns the texture.
    void upload_font_atlas(ImFontAtlas& atlas);

    /// Draws every command list: one glDrawElements per command with its scissor and texture.
    /// Sets all the GL state it needs (blend, scissor, viewport from DisplaySize*FramebufferScale).
    void render(const ImDrawData& draw_data);

  private:
    /// Points the vertex attributes at the vertex buffer from vertex `first` on (with the VAO and VBO bound):
    /// the base vertex of a command where glDrawElementsBaseVertex is missing (WebGL 2).
    void point_attributes(unsigned first);
    /// A part of a command's index range, drawn with one program, or an opaque rectangle cleared.
    struct Run {
        unsigned first = 0, count = 0; ///< Indices, from the command's first.
        bool solid = false;
        bool clear = false;                 ///< An opaque axis-aligned rectangle on pixel edges: glClear.
        int x0 = 0, y0 = 0, x1 = 0, y1 = 0; ///< Its pixels (top-left origin), when `clear`.
        unsigned colour = 0;                ///< Its colour (IM_COL32), when `clear`.
    };
    /// Splits a font-atlas command into textured runs and large runs of untextured (white-texel) triangles;
    /// large opaque rectangles whose edges lie on pixel edges (window backgrounds) become `clear` runs.
    void split_runs(const ImDrawList& list, const ImDrawCmd& cmd, float scale, float off_x, float off_y);
    /// Adds the solid triangles [from, to) of a command to runs_, the large opaque rectangles as clears.
    void add_solid(const ImDrawList& list, const ImDrawCmd& cmd, unsigned from, unsigned to, float scale,
                   float off_x, float off_y);
    void use_program(bool solid);

    const GlApi& gl_;
    ShaderProgram program_;
    ShaderProgram solid_program_; ///< The same without the texture fetch (imgui.frag.glsl, SOLID).
    GLint loc_proj_ = -1, loc_proj_solid_ = -1;
    GLint loc_tex_ = -1;
    GLuint vao_ = 0, vbo_ = 0, ebo_ = 0;
    GLuint font_texture_ = 0;
    float white_uv_[2] = {-1, -1}; ///< The atlas' white texel (ImFontAtlas::TexUvWhitePixel).
    std::vector<Run> runs_;
    bool solid_bound_ = false;
    unsigned attributes_at_ = 0; ///< The vertex the attributes point at (point_attributes).
};

} // namespace fv::gfx
