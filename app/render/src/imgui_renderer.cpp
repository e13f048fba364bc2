#include "fv/gfx/imgui_renderer.hpp"

#include <imgui.h>
#include <imgui_internal.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

namespace fv::gfx {
namespace {

// Untextured triangles worth a draw call of their own, in framebuffer pixels: window, child and frame
// backgrounds. Smaller runs stay with the text around them (same pixels either way, fewer draw calls).
constexpr float kMinSolidRunArea = 4096;

// Appends indices [first, first + count) to the runs, joined with the last run when it is of the same kind.
template <typename Run> void add_run(std::vector<Run>& runs, unsigned first, unsigned count, bool solid) {
    if (count == 0) return;
    if (!runs.empty() && !runs.back().clear && runs.back().solid == solid) {
        runs.back().count += count;
    } else {
        Run r;
        r.first = first, r.count = count, r.solid = solid;
        runs.push_back(r);
    }
}

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

void ImGuiRenderer::split_runs(const ImDrawList& list, const ImDrawCmd& cmd, float scale, float off_x,
                               float off_y) {
    runs_.clear();
    const ImDrawIdx* idx = list.IdxBuffer.Data + cmd.IdxOffset;
    const ImDrawVert* vtx = list.VtxBuffer.Data + cmd.VtxOffset;
    auto white = [&](const ImDrawVert& v) { return v.uv.x == white_uv_[0] && v.uv.y == white_uv_[1]; };
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
            add_run(runs_, textured_from, from - textured_from, false);
            add_solid(list, cmd, from, i, scale, off_x, off_y);
            textured_from = i;
        }
    }
    add_run(runs_, textured_from, cmd.ElemCount - textured_from, false);
}

void ImGuiRenderer::add_solid(const ImDrawList& list, const ImDrawCmd& cmd, unsigned from, unsigned to,
                              float scale, float off_x, float off_y) {
    const ImDrawIdx* idx = list.IdxBuffer.Data + cmd.IdxOffset;
    const ImDrawVert* vtx = list.VtxBuffer.Data + cmd.VtxOffset;
    // ImDrawList::PrimRect's two triangles (a, b, c), (a, c, d) with a top-left, c bottom-right, all in one
    // opaque colour, on pixel edges: exactly the pixels a scissored glClear of that colour writes (the blend
    // of an opaque colour is the colour; the alpha channel becomes 1 either way). llvmpipe clears tiles
    // almost for free, while it blends every pixel of the triangles.
    auto pixel = [scale](float v, float off, int& out) {
        const float p = (v - off) * scale;
        out = static_cast<int>(std::lround(p));
        return static_cast<float>(out) == p;
    };
    auto clearable = [&](unsigned i, Run& r) {
        if (i + 6 > to) return false;
        const ImDrawIdx a = idx[i], b = idx[i + 1], c = idx[i + 2], d = idx[i + 5];
        if (idx[i + 3] != a || idx[i + 4] != c) return false;
        const ImDrawVert &va = vtx[a], &vb = vtx[b], &vc = vtx[c], &vd = vtx[d];
        if ((va.col >> IM_COL32_A_SHIFT & 0xFF) != 0xFF || vb.col != va.col || vc.col != va.col ||
            vd.col != va.col)
            return false;
        if (vb.pos.y != va.pos.y || vb.pos.x != vc.pos.x || vd.pos.x != va.pos.x || vd.pos.y != vc.pos.y ||
            !(vc.pos.x > va.pos.x) || !(vc.pos.y > va.pos.y))
            return false;
        if (!pixel(va.pos.x, off_x, r.x0) || !pixel(va.pos.y, off_y, r.y0) || !pixel(vc.pos.x, off_x, r.x1) ||
            !pixel(vc.pos.y, off_y, r.y1))
            return false;
        if (static_cast<float>(r.x1 - r.x0) * static_cast<float>(r.y1 - r.y0) < kMinSolidRunArea)
            return false;
        r.colour = va.col;
        return true;
    };
    unsigned solid_from = from;
    for (unsigned i = from; i < to; i += 3) {
        Run r;
        if (!clearable(i, r)) continue;
        add_run(runs_, solid_from, i - solid_from, true);
        r.clear = true;
        runs_.push_back(r);
        i += 3; // the rectangle's second triangle
        solid_from = i + 3;
    }
    add_run(runs_, solid_from, to - solid_from, true);
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
            if (cmd.GetTexID() == atlas_id && scale.x == scale.y) {
                split_runs(*list, cmd, scale.x, off.x, off.y);
            } else {
                runs_.assign(1, Run{});
                runs_.back().count = cmd.ElemCount;
            }
            if (!gl_.DrawElementsBaseVertex && cmd.VtxOffset != attributes_at_)
                point_attributes(cmd.VtxOffset);
            const GLint sx0 = static_cast<GLint>(x0), sy1 = static_cast<GLint>(static_cast<float>(fb_h) - y1);
            const GLint sx1 = sx0 + static_cast<GLsizei>(x1 - x0), sy0 = sy1 + static_cast<GLsizei>(y1 - y0);
            for (const Run& run : runs_) {
                if (run.clear) {
                    // The rectangle (top-left origin) in GL's bottom-left one, within the command's scissor.
                    const GLint cx0 = std::max(run.x0, sx0), cx1 = std::min(run.x1, sx1);
                    const GLint cy0 = std::max(fb_h - run.y1, sy1), cy1 = std::min(fb_h - run.y0, sy0);
                    if (cx1 <= cx0 || cy1 <= cy0) continue;
                    gl_.Scissor(cx0, cy0, cx1 - cx0, cy1 - cy0);
                    auto channel = [&](int shift) {
                        return static_cast<float>(run.colour >> shift & 0xFF) / 255.0f;
                    };
                    gl_.ClearColor(channel(IM_COL32_R_SHIFT), channel(IM_COL32_G_SHIFT),
                                   channel(IM_COL32_B_SHIFT), 1.0f);
                    gl_.Clear(GL_COLOR_BUFFER_BIT);
                    gl_.Scissor(sx0, sy1, sx1 - sx0, sy0 - sy1);
                    continue;
                }
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
