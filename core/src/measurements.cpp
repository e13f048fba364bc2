#include "fv/measurements.hpp"

#include "fv/input_file.hpp"
#include "fv/printable_text.hpp"
#include "fv/read_number.hpp"

#include "fv/units.hpp"

#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace fv {

namespace {

std::string where(const std::string& file, int line, int column) {
    if (line <= 0) return file + ": ";
    return file + ":" + std::to_string(line) + ":" + std::to_string(column) + ": ";
}

// Offending text as it may appear in a one-line message (the file may be binary junk).
std::string quote(std::string_view s) {
    return quoted_text(s, 32);
}

enum class Col { zeta, vb, rx, theta, sigma, label, count };
constexpr std::array<const char*, static_cast<int>(Col::count)> kNames{"zeta",      "vb",    "r_x",
                                                                       "theta_deg", "sigma", "label"};
constexpr const char* kAllowedNames = "zeta, vb, r_x, theta_deg, sigma, label";

bool blank(char c) {
    return c == ' ' || c == '\t';
}

struct Field {
    std::string_view text; // trimmed
    int column = 0;        // 1-based byte column of its first non-blank byte (or of its start when empty)
    std::size_t start = 0; // 0-based offset of its first byte; the separating comma is just before it
};

std::vector<Field> split(std::string_view line) {
    std::vector<Field> fields;
    std::size_t start = 0;
    while (true) {
        const std::size_t comma = line.find(',', start);
        const std::size_t end = comma == std::string_view::npos ? line.size() : comma;
        std::size_t a = start, b = end;
        while (a < b && blank(line[a])) ++a;
        while (b > a && blank(line[b - 1])) --b;
        fields.push_back({line.substr(a, b - a), static_cast<int>((a < end ? a : start) + 1), start});
        if (comma == std::string_view::npos) break;
        start = comma + 1;
    }
    return fields;
}

class Parser {
  public:
    Parser(std::string_view text, const std::string& name, const ReadOptions& opt)
        : text_(text), name_(name), opt_(opt) {}

    MeasurementSet run();

  private:
    [[noreturn]] void fail(int column, const std::string& message) const {
        throw DataError(name_, line_no_, column, message);
    }
    void header(std::string_view line);
    void row(std::string_view line);
    double number(const Field& f, Col c, ParamRange r) const;

    std::string_view text_;
    const std::string& name_;
    const ReadOptions& opt_;
    int line_no_ = 0;
    std::array<int, static_cast<int>(Col::count)> index_{}; // field index + 1 of each column, 0 if absent
    std::size_t n_columns_ = 0;
    MeasurementSet set_;
};

void Parser::header(std::string_view line) {
    const std::vector<Field> fields = split(line);
    for (std::size_t k = 0; k < fields.size(); ++k) {
        const Field& f = fields[k];
        int c = 0;
        while (c < static_cast<int>(Col::count) && f.text != kNames[static_cast<std::size_t>(c)]) ++c;
        if (f.text.empty()) fail(f.column, "empty column name; allowed: " + std::string(kAllowedNames));
        if (c == static_cast<int>(Col::count))
            fail(f.column, "unknown column " + quote(f.text) + "; allowed: " + kAllowedNames);
        if (index_[static_cast<std::size_t>(c)] != 0)
            fail(f.column, "duplicate column " + quote(f.text) + "; each column may appear once");
        index_[static_cast<std::size_t>(c)] = static_cast<int>(k + 1);
    }
    n_columns_ = fields.size();
    const auto has = [&](Col c) { return index_[static_cast<std::size_t>(c)] != 0; };
    const auto column_of = [&](Col c) {
        return fields[static_cast<std::size_t>(index_[static_cast<std::size_t>(c)] - 1)].column;
    };
    if (has(Col::zeta) && has(Col::vb))
        fail(column_of(Col::vb), "both 'zeta' and 'vb' columns; give one of them");
    if (!has(Col::zeta) && !has(Col::vb))
        fail(1, "missing required column 'zeta' or 'vb'; required: 'zeta,r_x' or 'vb,r_x'");
    if (!has(Col::rx)) fail(1, "missing required column 'r_x'; required: 'zeta,r_x' or 'vb,r_x'");
    if (has(Col::vb) && (!opt_.amplitude_um || !opt_.frequency_khz))
        fail(column_of(Col::vb), "column 'vb' (m/s) needs the vibration amplitude (um) and frequency (kHz) "
                                 "to convert it to zeta; give them, or use a 'zeta' column");
    if (has(Col::vb)) {
        try {
            units::vibration_velocity(*opt_.amplitude_um, *opt_.frequency_khz);
        } catch (const units::UnitError& e) {
            fail(column_of(Col::vb), std::string("column 'vb' cannot be converted: ") + e.what());
        }
    }
    set_.from_vb = has(Col::vb);
    set_.has_theta = has(Col::theta);
    set_.has_sigma = has(Col::sigma);
}

double Parser::number(const Field& f, Col c, ParamRange r) const {
    double v = 0;
    // The shared reader (fv/read_number.hpp): the verdicts and messages of the command line and the links.
    if (std::string why = read_number(kNames[static_cast<std::size_t>(c)], f.text, r, v); !why.empty())
        fail(f.column, why);
    return v;
}

void Parser::row(std::string_view line) {
    const std::vector<Field> fields = split(line);
    if (fields.size() != n_columns_) {
        const int column = fields.size() > n_columns_
                               ? static_cast<int>(fields[n_columns_].start) // the extra comma
                               : static_cast<int>(line.size() + 1);
        fail(column, std::to_string(fields.size()) + " fields, but the header has " +
                         std::to_string(n_columns_) + "; every row needs one field per column");
    }
    if (set_.points.size() >= opt_.max_rows)
        fail(1, "more than " + std::to_string(opt_.max_rows) + " data rows; allowed: at most " +
                    std::to_string(opt_.max_rows));
    const auto field = [&](Col c) -> const Field* {
        const int k = index_[static_cast<std::size_t>(c)];
        return k == 0 ? nullptr : &fields[static_cast<std::size_t>(k - 1)];
    };
    Measurement m;
    m.line = line_no_;
    if (const Field* f = field(Col::zeta)) m.zeta = number(*f, Col::zeta, kZetaRange);
    if (const Field* f = field(Col::vb)) {
        const double vb = number(*f, Col::vb, kVbRange);
        m.vb = vb;
        try {
            m.zeta = units::zeta_from_vb(vb, *opt_.amplitude_um, *opt_.frequency_khz);
        } catch (const units::UnitError&) {
            m.zeta = HUGE_VAL; // vb / v_v beyond the doubles: reported as out of the zeta range below
        }
        if (!(m.zeta <= kMaxZeta)) // also NaN
            fail(f->column, "vb = " + printable_text(f->text) + " gives zeta = " + shortest_decimal(m.zeta) +
                                "; allowed: zeta in " + describe(kZetaRange));
    }
    m.rx = number(*field(Col::rx), Col::rx, kRxDataRange);
    if (const Field* f = field(Col::theta)) m.theta_deg = number(*f, Col::theta, kThetaRange);
    if (const Field* f = field(Col::sigma)) m.sigma = number(*f, Col::sigma, kSigmaRange);
    if (const Field* f = field(Col::label)) {
        if (std::string why = text_error(f->text, kMaxLabelBytes); !why.empty())
            fail(f->column, "label: " + why);
        m.label = std::string(f->text);
    }
    set_.points.push_back(std::move(m));
}

MeasurementSet Parser::run() {
    set_.file = name_;
    std::string_view rest = text_;
    if (rest.substr(0, 3) == "\xEF\xBB\xBF") rest.remove_prefix(3);
    // A file cut at max_file_bytes is reported where the cut falls, so the limit reads like any other error.
    const bool cut = rest.size() > opt_.max_file_bytes;
    if (cut) rest = rest.substr(0, opt_.max_file_bytes);
    bool have_header = false;
    while (!rest.empty()) {
        ++line_no_;
        const std::size_t nl = rest.find('\n');
        std::string_view line = rest.substr(0, nl);
        rest = nl == std::string_view::npos ? std::string_view{} : rest.substr(nl + 1);
        if (cut && rest.empty())
            fail(static_cast<int>(line.size() + 1),
                 "file larger than " + std::to_string(opt_.max_file_bytes) + " bytes; allowed: at most that");
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        if (line.size() > opt_.max_line_bytes)
            fail(static_cast<int>(opt_.max_line_bytes + 1),
                 "line longer than " + std::to_string(opt_.max_line_bytes) + " bytes; allowed: at most that");
        if (const std::size_t nul = line.find('\0'); nul != std::string_view::npos)
            fail(static_cast<int>(nul + 1), "NUL byte; allowed: a text file");
        std::size_t first = 0;
        while (first < line.size() && blank(line[first])) ++first;
        if (first == line.size()) continue;
        if (line[first] == '#') {
            std::string lower(line.substr(first));
            for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
            set_.synthetic = set_.synthetic || lower.find("synthetic") != std::string::npos;
            continue;
        }
        if (!have_header) {
            header(line);
            have_header = true;
        } else {
            row(line);
        }
    }
    ++line_no_;
    if (!have_header) fail(1, "no header line; expected e.g. 'zeta,r_x' (file empty or only comments)");
    if (set_.points.empty()) fail(1, "no data rows after the header; expected at least one");
    return std::move(set_);
}

} // namespace

DataError::DataError(std::string file_, int line_, int column_, const std::string& message_)
    : std::runtime_error(where(file_, line_, column_) + message_), file(std::move(file_)), line(line_),
      column(column_), message(message_) {}

MeasurementSet parse_measurements(std::string_view text, const std::string& name, const ReadOptions& opt) {
    return Parser(text, name, opt).run();
}

MeasurementSet read_measurements(const std::string& path, const ReadOptions& opt) {
    // At most one byte past the limit: enough to know the file is too big, without reading a huge one. A
    // directory, a socket, a terminal or a FIFO nobody writes to is an error, not a hang (input_file.hpp).
    std::string text;
    InputLimits limits;
    limits.max_bytes = opt.max_file_bytes;
    if (auto why = read_input_file(path, text, limits); !why.empty()) throw DataError(path, 0, 0, why);
    return parse_measurements(text, path, opt);
}

} // namespace fv
