#include "figures/render_figures.hpp"

#include "fv/atomic_file.hpp"
#include "fv/gfx/png.hpp"
#include "fv/gfx/vector_output.hpp"

#include <algorithm>
#include <atomic>
#include <deque>
#include <future>
#include <memory>
#include <optional>

namespace fv::app {

std::vector<std::string> PictureFormats::extensions() const {
    std::vector<std::string> e;
    if (png) e.push_back("png");
    if (svg) e.push_back("svg");
    if (pdf) e.push_back("pdf");
    return e;
}

std::vector<NamedFile> encode_pictures(const std::string& id, const PictureFormats& formats,
                                       const gfx::Image& image, const gfx::DisplayList& list) {
    std::vector<NamedFile> files;
    if (formats.png) {
        const std::vector<unsigned char> png = gfx::encode_png(image);
        files.emplace_back(id + ".png", std::string(reinterpret_cast<const char*>(png.data()), png.size()));
    }
    if (formats.svg) files.emplace_back(id + ".svg", gfx::render_vector(list, gfx::VectorFormat::Svg));
    if (formats.pdf) files.emplace_back(id + ".pdf", gfx::render_vector(list, gfx::VectorFormat::Pdf));
    return files;
}

namespace {

// A drawn figure on its way to the disk: its frame and display list (freed once encoded) and the files
// beside its pictures.
struct Drawn {
    std::string id;
    gfx::Image image;
    gfx::DisplayList list;
    std::vector<NamedFile> files;
};

// nullopt: not written (an earlier write failed); "": written; else the failure.
using WriteResult = std::shared_future<std::optional<std::string>>;

// Encodes one figure (in parallel with the others) and writes its files once the figure before it is written
// (`before`), unless a write failed meanwhile (`stop`, set by the first failure): nothing after a failed
// write is written.
std::optional<std::string> encode_and_write(const RenderJob& job, Drawn d, WriteResult before,
                                            std::atomic<bool>& stop) {
    std::vector<NamedFile> files;
    std::string err;
    try {
        files = encode_pictures(d.id, job.formats, d.image, d.list);
    } catch (const std::exception& e) {
        err = d.id + ": " + e.what();
    }
    std::vector<std::uint8_t>().swap(d.image.rgba);
    d.list = {};
    if (before.valid()) before.wait();
    if (stop) return std::nullopt;
    files.insert(files.end(), d.files.begin(), d.files.end());
    for (const auto& [file, content] : files)
        if (err.empty()) err = write_file_atomic(job.dir + "/" + file, content);
    if (!err.empty()) stop = true;
    return err;
}

} // namespace

RenderOutcome render_figures(RenderSession& session, std::vector<FigureSpec>& specs, const RenderJob& job) {
    RenderOutcome out;
    auto stop = std::make_shared<std::atomic<bool>>(false);
    std::deque<std::pair<WriteResult, std::string>> pending; // jobs in flight, oldest first, with their ids
    // The oldest job's end, in figure order (so that `wrote` comes in order too).
    auto finish_oldest = [&] {
        const std::optional<std::string> err = pending.front().first.get();
        const std::string id = std::move(pending.front().second);
        pending.pop_front();
        if (err && err->empty() && job.wrote) job.wrote(id);
        if (err && !err->empty() && out.write_error.empty()) out.write_error = *err;
    };
    for (FigureSpec& spec : specs) {
        if (*stop) break; // after the first failed write nothing else is computed
        FigureData data = compute_figure(spec);
        FigureExtras extras = job.extras ? job.extras(spec, data) : FigureExtras{};
        if (!extras.failed.empty()) {
            ++out.failed_figures;
            out.failed += (out.failed.empty() ? "" : "; ") + extras.failed;
        }
        Drawn d{data.id, {}, {}, std::move(extras.files)};
        // GL is single-threaded: the drawing happens here, the encoding on the job's thread.
        if (job.formats.png) {
            d.image = session.render_figure(data);
            if (job.formats.svg || job.formats.pdf) d.list = session.canvas().display_list();
        } else {
            d.list = session.record_figure(data);
        }
        spec = FigureSpec{}; // its data (fig19's figure) are not needed any more
        while (pending.size() >= std::max<std::size_t>(job.encoders, 1)) finish_oldest();
        const std::string id = d.id;
        WriteResult before = pending.empty() ? WriteResult() : pending.back().first;
        pending.emplace_back(std::async(std::launch::async, encode_and_write, std::cref(job), std::move(d),
                                        std::move(before), std::ref(*stop))
                                 .share(),
                             id);
    }
    while (!pending.empty()) finish_oldest();
    return out;
}

} // namespace fv::app
