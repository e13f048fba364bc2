#include "animation_export.hpp"
#include "dialog_footer.hpp"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cstdio>

#if defined(__linux__)
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

namespace fv::app {

AnimationExportJob::AnimationExportJob(AnimationExporter exporter) : exporter_(std::move(exporter)) {}

AnimationExportJob::~AnimationExportJob() {
    cancel_ = true;
    if (thread_.joinable()) thread_.join();
}

std::string AnimationExportJob::start(const AnimationRequest& r) {
    if (!exporter_) {
        failed_ = true;
        return "animation export is not available in this build";
    }
    if (running_) {
        failed_ = true;
        return "an animation export is running (" + std::to_string(done_) + "/" + std::to_string(total_) +
               " frames); wait for it";
    }
    if (thread_.joinable()) thread_.join();
    {
        std::lock_guard<std::mutex> lock(mutex_);
        path_ = r.path;
        result_.clear();
        finished_ = false;
    }
    done_ = 0;
    total_ = 0;
    shown_ = -1;
    cancel_ = false;
    running_ = true;
    thread_ = std::thread([this, r] {
    // Below the window's thread: on two cores the frames on screen come first. llvmpipe's threads, made
    // by this thread's context, inherit the priority.
#if defined(__linux__)
        ::setpriority(PRIO_PROCESS, static_cast<id_t>(::syscall(SYS_gettid)), 10);
#endif
        std::string err;
        try {
            err = exporter_(
                r,
                [this](int done, int total) {
                    total_ = total;
                    done_ = done;
                },
                cancel_);
        } catch (const std::exception& e) {
            err = e.what();
        }
        std::lock_guard<std::mutex> lock(mutex_);
        result_ = err;
        finished_ = true;
        running_ = false;
    });
    return "exporting " + r.path + " in the background…";
}

std::optional<std::string> AnimationExportJob::poll() {
    std::lock_guard<std::mutex> lock(mutex_);
    if (finished_) {
        finished_ = false;
        shown_ = -1;
        const int frames = total_;
        if (!result_.empty()) {
            failed_ = true;
            return "animation not written: " + result_;
        }
        return "wrote " + path_ + " (" + std::to_string(frames) + " frames, a seamless loop)";
    }
    if (!running_ || done_ == shown_) return std::nullopt;
    shown_ = done_;
    return "exporting " + path_ + ": " + std::to_string(done_) + "/" + std::to_string(total_) + " frames…";
}

void AnimationExportJob::wait() {
    if (thread_.joinable()) thread_.join();
}

std::optional<AnimationRequest> draw_export_dialog(ExportDialog& d, double speed, bool busy) {
    if (d.open_requested) {
        ImGui::OpenPopup("Export animation");
        d.open_requested = false;
        d.error.clear();
    }
    // At most the page's width less a margin (a phone's page is 390 wide).
    ImGui::SetNextWindowSize(
        ImVec2(std::min(ImGui::GetFontSize() * 30, ImGui::GetIO().DisplaySize.x - 16), 0),
        ImGuiCond_Appearing);
    if (!ImGui::BeginPopupModal("Export animation", nullptr, ImGuiWindowFlags_NoSavedSettings)) return {};
    std::optional<AnimationRequest> out;
    ImGui::TextWrapped("A seamless loop of the steady state at the current parameters, %d periods at %.2g "
                       "periods per second (the speed slider), 30 frames per second, 960x600, made in the "
                       "background. The same as `frictionviz animate`.",
                       d.periods, speed);
    if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
    ImGui::SetNextItemWidth(-1);
    const bool enter = ImGui::InputText("##path", &d.path, ImGuiInputTextFlags_EnterReturnsTrue);
    // The format follows the extension; the buttons rewrite it.
    const std::optional<AnimationFormat> f = animation_format(d.path);
    auto set_ext = [&](const char* ext) {
        const auto dot = d.path.find_last_of('.'), slash = d.path.find_last_of('/');
        if (dot != std::string::npos && (slash == std::string::npos || dot > slash + 1)) d.path.erase(dot);
        d.path += ext;
    };
    if (ImGui::RadioButton("GIF (loops by itself in any slide or page)", f == AnimationFormat::gif))
        set_ext(".gif");
    if (ImGui::RadioButton("MP4, H.264 (smaller; set it to loop in the slide)", f == AnimationFormat::mp4))
        set_ext(".mp4");
    ImGui::RadioButton("dashboard (top view, force, lower panel)", &d.view, 0);
    ImGui::SameLine();
    ImGui::RadioButton("top view alone", &d.view, 1);
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 6);
    ImGui::InputInt("periods", &d.periods);
    d.periods = std::clamp(d.periods, 1, 20);
    if (!d.error.empty()) ImGui::TextColored(ImVec4(0.8f, 0.2f, 0.1f, 1), "%s", d.error.c_str());
    ImGui::BeginDisabled(busy);
    const bool go = ImGui::Button("Export") || enter;
    ImGui::EndDisabled();
    if (go && !busy) {
        if (!animation_format(d.path)) {
            d.error = "the file name must end in .gif or .mp4";
        } else {
            AnimationRequest r;
            r.path = d.path;
            r.spec.view = d.view == 1 ? AnimationView::scene : AnimationView::dashboard;
            r.spec.periods = d.periods;
            r.spec.speed = std::clamp(speed, 0.05, 10.0);
            out = r;
            ImGui::CloseCurrentPopup();
        }
    }
    end_dialog_with_cancel();
    return out;
}

} // namespace fv::app
