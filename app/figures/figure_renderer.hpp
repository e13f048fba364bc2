// The figures layer's public entry point (the installed package, docs/library.md): a registered figure's
// definition by id, its picture as the bytes of a PNG, SVG or PDF file, drawn headless, and its tables as
// the CSV files `frictionviz render` writes. The pictures are
// those of `frictionviz render` at the same size and scale, byte for byte: both draw through RenderSession
// and encode with the render layer's encoders. The rest of app/figures (the session, the painters) is the
// app's and is not installed.
#pragma once

#include "fv/figure_data.hpp"
#include "fv/figure_registry.hpp"

#include <memory>
#include <string>
#include <vector>

namespace fv::app {

class RenderSession;

// The sizes a picture may have, for the library and for the command line's --size and --scale: the image in
// pixels, its pixels per logical unit, and the logical page (size / scale) the figure layout needs at least
// and at most.
inline constexpr int kMinSizeW = 320, kMinSizeH = 240, kMaxSizeW = 7680, kMaxSizeH = 4320;
inline constexpr double kMinScale = 0.25, kMaxScale = 8;
inline constexpr int kMinPageW = 320, kMinPageH = 240, kMaxPageW = 7680, kMaxPageH = 4320;

enum class PictureFormat { png, svg, pdf };
// "png", "svg", "pdf": the file extension.
const char* to_string(PictureFormat f);

struct PictureSize {
    int width = 1280, height = 800; // the PNG's pixels (render --size)
    double scale = 1;               // pixels per logical unit (render --scale); SVG and PDF pages are
                                    // width/scale x height/scale points
};

// "" if `size` is allowed (the limits above), else a one-line reason naming the value and the allowed range.
std::string picture_size_error(const PictureSize& size);

// The definition of the registered figure `id` (fv/figure_registry.hpp: "fig10", "scene", "map", ...) for
// `inputs`; inputs left unset are not given. Throws std::invalid_argument with a one-line message for an
// unknown id (naming the known ones), a required input not given or an input the figure does not admit
// (fv::input_error: a list where it takes one value, a value out of range, too many curves), and what the
// figure's definition throws for a data file (fv::DataError, fv::FitError: fig19). compute_figure
// (fv/figure_data.hpp) turns it into numbers.
FigureSpec registered_figure(const std::string& id, const FigureInputs& inputs = {});

// One table of a computed figure as `frictionviz render` writes it beside the picture: the file's name (the
// figure's id, the table's suffix, ".csv": "map.csv", "map-best-angle.csv") and its CSV text, byte for byte
// the command line's (one writer for both).
struct FigureTableFile {
    std::string name;
    std::string csv;
};

// Every table of `figure`, in its order (ID.csv first).
std::vector<FigureTableFile> figure_tables(const FigureData& figure);

// One table's CSV text: ratio rows (model,i,theta_deg,rdisp,zeta,r_x,r_y,periods,error_estimate,status,...),
// a steady period's samples (tau,Px,Py,Tx,Ty,z,Fx,Fy,status) or a ready-made table (the map's best angles).
std::string table_csv(const TableData& table);

// A headless GL context (OSMesa, loaded at run time) with the fonts and canvas, made once and reused for any
// number of figures. Not thread-safe: one renderer per thread.
class FigureRenderer {
  public:
    // Throws std::invalid_argument if the size is not allowed (picture_size_error), std::runtime_error with a
    // one-line reason if no headless context can be made (libOSMesa or the DejaVu font missing).
    explicit FigureRenderer(const PictureSize& size = {});
    ~FigureRenderer();
    FigureRenderer(const FigureRenderer&) = delete;
    FigureRenderer& operator=(const FigureRenderer&) = delete;

    // The picture of a computed figure as the content of an ID.png, ID.svg or ID.pdf file. Throws
    // std::runtime_error if an encoder fails. Write it with fv::write_file_atomic (fv/atomic_file.hpp).
    std::string render(const FigureData& figure, PictureFormat format);

  private:
    std::unique_ptr<RenderSession> session_;
};

} // namespace fv::app
