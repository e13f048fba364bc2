#include "fv/gfx/imgui_renderer.hpp"

#include <imgui.h>
#include <imgui_internal.h>

#include <cmath>
#include <cstddef>
#include <cstdint>

namespace fv::gfx {
namespace {

// Untextured triangles worth a draw call of their own, in framebuffer pixels: window, child and frame
// backgrounds. Smaller runs stay with the text around them (same pixels either way, fewer draw calls).
constexpr float kMinSolidRunArea = 4096;

} // namespace

ImGuiRenderer::ImGuiRenderer(const GlApi& gl)
    : gl_(gl), program_(gl, "imgui.vert.glsl", "imgui.frag.glsl"),
      solid_program_(gl, "imgui.vert.glsl", "imgui.frag.glsl", "#define SOLID 1\n") {
    loc_proj_ = program_.uniform("u_proj");
    loc_proj_solid_ = solid_program_.uniform("u_proj");
    loc_tex_ = program_.uniform("u_tex");
    gl_.GenVertexArrays(1, &vao_);
    gl_.GenBuffers(1, &vbo_);
    gl_.GenBuffers(1, &ebo_);
    gl_.BindVertexArray(vao_);
    gl_.BindBuffer(GL_ARRAY_BUFFER, vbo_);
    gl_.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, ebo_);
    gl_.EnableVertexAttribArray(0);
    gl_.EnableVertexAttribArray(1);
    gl_.EnableVertexAttribArray(2);
    point_attributes(0);
    gl_.BindVertexArray(0);
}

void ImGuiRenderer::point_attributes(unsigned first) {
    const auto stride = static_cast<GLsizei>(sizeof(ImDrawVert));
    const std::size_t base = std::size_t{first} * sizeof(ImDrawVert);
    gl_.VertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, stride,
                            reinterpret_cast<void*>(base + offsetof(ImDrawVert, pos)));
    gl_.VertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, stride,
                            reinterpret_cast<void*>(base + offsetof(ImDrawVert, uv)));
    gl_.VertexAttribPointer(2, 4, GL_UNSIGNED_BYTE, GL_TRUE, stride,
                            reinterpret_cast<void*>(base + offsetof(ImDrawVert, col)));
    attributes_at_ = first;
}

ImGuiRenderer::~ImGuiRenderer() {
    if (font_texture_) gl_.DeleteTextures(1, &font_texture_);
    gl_.DeleteBuffers(1, &ebo_);
    gl_.DeleteBuffers(1, &vbo_);
    gl_.DeleteVertexArrays(1, &vao_);
}

void ImGuiRenderer::upload_font_atlas(ImFontAtlas& atlas) {
    unsigned char* pixels = nullptr;
    int w = 0, h = 0;
    atlas.GetTexDataAsRGBA32(&pixels, &w, &h);
    if (!font_texture_) gl_.GenTextures(1, &font_texture_);
    gl_.ActiveTexture(GL_TEXTURE0);
    gl_.BindTexture(GL_TEXTURE_2D, font_texture_);
    // Linear filtering: glyphs are drawn at fractional scales (sub/superscripts, HiDPI).
    gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    gl_.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
    gl_.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
    atlas.SetTexID(reinterpret_cast<ImTextureID>(static_cast<std::uintptr_t>(font_texture_)));
    white_uv_[0] = atlas.TexUvWhitePixel.x;
    white_uv_[1] = atlas.TexUvWhitePixel.y;
}

void ImGuiRenderer::split_runs(const ImDrawList& list, const ImDrawCmd& cmd, float scale) {
    runs_.clear();
    const ImDrawIdx* idx = list.IdxBuffer.Data + cmd.IdxOffset;
    const ImDrawVert* vtx = list.VtxBuffer.Data + cmd.VtxOffset;
    auto white = [&](const ImDrawVert& v) { return v.uv.x == white_uv_[0] && v.uv.y == white_uv_[1]; };
    auto add = [&](unsigned first, unsigned count, bool solid) {
        if (count == 0) return;
        if (!runs_.empty() && runs_.back().solid == solid) {
            runs_.back().count += count;
        } else {
            runs_.push_back({first, count, solid});
        }
    };
    auto solid = [&](unsigned i) {
        return white(vtx[idx[i]]) && white(vtx[idx[i + 1]]) && white(vtx[idx[i + 2]]);
    };
    auto area = [&](unsigned i) {
        const ImVec2 a = vtx[idx[i]].pos, b = vtx[idx[i + 1]].pos, c = vtx[idx[i + 2]].pos;
        return 0.5f * std::fabs((b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y)) * scale * scale;
    };
    const unsigned n = cmd.ElemCount - cmd.ElemCount % 3;
    unsigned textured_from = 0; // the first index not in a run yet
    for (unsigned i = 0; i < n;) {
        if (!solid(i)) {
            i += 3;
            continue;
        }
        const unsigned from = i;
        float covered = 0;
        for (; i < n && solid(i); i += 3) covered += area(i);
        if (covered >= kMinSolidRunArea) {
            add(textured_from, from - textured_from, false);
            add(from, i - from, true);
            textured_from = i;
        }
    }
    add(textured_from, cmd.ElemCount - textured_from, false);
}

void ImGuiRenderer::use_program(bool solid) {
    if (solid == solid_bound_) return;
    gl_.UseProgram(solid ? solid_program_.id() : program_.id());
    solid_bound_ = solid;
}

void ImGuiRenderer::render(const ImDrawData& dd) {
    const int fb_w = static_cast<int>(dd.DisplaySize.x * dd.FramebufferScale.x);
    const int fb_h = static_cast<int>(dd.DisplaySize.y * dd.FramebufferScale.y);
    if (fb_w <= 0 || fb_h <= 0 || dd.CmdListsCount == 0) return;

    gl_.Enable(GL_BLEND);
    gl_.BlendEquation(GL_FUNC_ADD);
    // Straight alpha for colour; alpha channel accumulates coverage so an opaque background stays opaque.
    gl_.BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    gl_.Disable(GL_CULL_FACE);
    gl_.Disable(GL_DEPTH_TEST);
    gl_.Disable(GL_STENCIL_TEST);
    gl_.Enable(GL_SCISSOR_TEST);
    gl_.Viewport(0, 0, fb_w, fb_h);

    const float l = dd.DisplayPos.x, r = dd.DisplayPos.x + dd.DisplaySize.x;
    const float t = dd.DisplayPos.y, b = dd.DisplayPos.y + dd.DisplaySize.y;
    const float proj[16] = {
        2.0f / (r - l),    0, 0, 0, 0, 2.0f / (t - b), 0, 0, 0, 0, -1, 0, (r + l) / (l - r),
        (t + b) / (b - t), 0, 1};
    gl_.UseProgram(solid_program_.id());
    gl_.UniformMatrix4fv(loc_proj_solid_, 1, GL_FALSE, proj);
    gl_.UseProgram(program_.id());
    gl_.UniformMatrix4fv(loc_proj_, 1, GL_FALSE, proj);
    gl_.Uniform1i(loc_tex_, 0);
    solid_bound_ = false;
    gl_.ActiveTexture(GL_TEXTURE0);
    gl_.BindVertexArray(vao_);
    gl_.BindBuffer(GL_ARRAY_BUFFER, vbo_);
    gl_.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, ebo_);

    const ImVec2 off = dd.DisplayPos;
    const ImVec2 scale = dd.FramebufferScale;
    const GLenum idx_type = sizeof(ImDrawIdx) == 2 ? GL_UNSIGNED_SHORT : GL_UNSIGNED_INT;
    const auto atlas_id = reinterpret_cast<ImTextureID>(static_cast<std::uintptr_t>(font_texture_));
    for (int n = 0; n < dd.CmdListsCount; ++n) {
        const ImDrawList* list = dd.CmdLists[n];
        gl_.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(list->VtxBuffer.Size) * sizeof(ImDrawVert),
                       list->VtxBuffer.Data, GL_STREAM_DRAW);
        gl_.BufferData(GL_ELEMENT_ARRAY_BUFFER,
                       static_cast<GLsizeiptr>(list->IdxBuffer.Size) * sizeof(ImDrawIdx),
                       list->IdxBuffer.Data, GL_STREAM_DRAW);
        for (const ImDrawCmd& cmd : list->CmdBuffer) {
            if (cmd.UserCallback) {
                // ResetRenderState has no meaning for us beyond what we set per command.
                if (cmd.UserCallback != ImDrawCallback_ResetRenderState) cmd.UserCallback(list, &cmd);
                continue;
            }
            if (cmd.ElemCount == 0) continue;
            // Clip rectangle in framebuffer pixels; GL scissor has a bottom-left origin.
            // Clamped to the framebuffer: clip rects may be "infinite" (e.g. for rotated text).
            const float fw = static_cast<float>(fb_w), fh = static_cast<float>(fb_h);
            const float x0 = ImClamp((cmd.ClipRect.x - off.x) * scale.x, 0.0f, fw);
            const float y0 = ImClamp((cmd.ClipRect.y - off.y) * scale.y, 0.0f, fh);
            const float x1 = ImClamp((cmd.ClipRect.z - off.x) * scale.x, 0.0f, fw);
            const float y1 = ImClamp((cmd.ClipRect.w - off.y) * scale.y, 0.0f, fh);
            if (x1 <= x0 || y1 <= y0) continue;
            gl_.Scissor(static_cast<GLint>(x0), static_cast<GLint>(static_cast<float>(fb_h) - y1),
                        static_cast<GLsizei>(x1 - x0), static_cast<GLsizei>(y1 - y0));
            gl_.BindTexture(GL_TEXTURE_2D,
                            static_cast<GLuint>(reinterpret_cast<std::uintptr_t>(cmd.GetTexID())));
            if (cmd.GetTexID() == atlas_id) {
                split_runs(*list, cmd, scale.x);
            } else {
                runs_.assign(1, Run{0, cmd.ElemCount, false});
            }
            if (!gl_.DrawElementsBaseVertex && cmd.VtxOffset != attributes_at_)
                point_attributes(cmd.VtxOffset);
            for (const Run& run : runs_) {
                use_program(run.solid);
                const auto count = static_cast<GLsizei>(run.count);
                void* const first_index =
                    reinterpret_cast<void*>((cmd.IdxOffset + run.first) * sizeof(ImDrawIdx));
                if (gl_.DrawElementsBaseVertex) {
                    gl_.DrawElementsBaseVertex(GL_TRIANGLES, count, idx_type, first_index,
                                               static_cast<GLint>(cmd.VtxOffset));
                } else {
                    gl_.DrawElements(GL_TRIANGLES, count, idx_type, first_index);
                }
            }
        }
    }
    gl_.BindVertexArray(0);
    gl_.Disable(GL_SCISSOR_TEST);
}

} // namespace fv::gfx
