// libFuzzer target for the output-path policy (fv/atomic_file.hpp). The input picks a path inside a scratch
// directory holding files, directories, symbolic links (chains, dangling ones, a loop) and a FIFO; the path
// is written. Broken guarantees abort (and so count as crashes):
//   - nothing outside the scratch directory changes;
//   - inside it, only the file the policy resolved the path to changes, and on failure nothing does;
//   - a written file holds exactly the data; no temporary file is left; links stay links.
#include "fv/atomic_file.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

namespace fs = std::filesystem;

namespace {

[[noreturn]] void broken(const std::string& what, const std::string& path) {
    std::fprintf(stderr, "broken guarantee: %s (path '%s')\n", what.c_str(), path.c_str());
    std::abort();
}

std::string slurp(const fs::path& p) {
    std::ifstream f(p, std::ios::binary);
    std::stringstream ss;
    ss << f.rdbuf();
    return ss.str();
}

// Every entry under `root`: its kind and, for files, content; for links, where they point.
std::map<std::string, std::string> snapshot(const fs::path& root) {
    std::map<std::string, std::string> m;
    std::error_code ec;
    for (auto it = fs::recursive_directory_iterator(root, ec);
         !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
        const fs::path p = it->path();
        const auto st = fs::symlink_status(p);
        std::string v;
        if (fs::is_symlink(st))
            v = "link:" + fs::read_symlink(p).string();
        else if (fs::is_regular_file(st))
            v = "file:" + slurp(p);
        else if (fs::is_directory(st))
            v = "dir";
        else if (fs::is_fifo(st))
            v = "fifo";
        else
            v = "other";
        m[p.lexically_relative(root).string()] = v;
    }
    return m;
}

// The names directly in `dir`, sorted (a left-over temporary file would show).
std::vector<std::string> listing(const fs::path& dir) {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

struct Fixture {
    fs::path outer, scratch;

    Fixture() {
        char tmpl[] = "/tmp/fv-fuzz-out-XXXXXX";
        outer = ::mkdtemp(tmpl);
        scratch = outer / "s";
        std::ofstream(outer / "sentinel") << "outside the scratch directory";
    }
    // The scratch directory, rebuilt for each input.
    void reset() {
        fs::remove_all(scratch);
        fs::create_directories(scratch / "d" / "e");
        std::ofstream(scratch / "f") << "F";
        std::ofstream(scratch / "d" / "g.csv") << "G";
        fs::create_symlink("f", scratch / "l");
        fs::create_symlink("l", scratch / "c");
        fs::create_symlink("new.csv", scratch / "dl");
        fs::create_symlink("d/e/deep.csv", scratch / "dd");
        fs::create_symlink("nowhere/x", scratch / "dx");
        fs::create_symlink("la", scratch / "lb");
        fs::create_symlink("lb", scratch / "la");
        fs::create_symlink("d", scratch / "dirlink");
        fs::create_symlink("../f", scratch / "d" / "up");
        ::mkfifo((scratch / "p").c_str(), 0600);
    }
};

const char* const kTokens[] = {"d",  "e",       "f",  "g.csv", "l",       "c", "dl", "dd", "dx", "la",
                               "lb", "dirlink", "up", "p",     "new.csv", "x", ".",  "..", "",   "deep.csv"};

// The path the input spells, relative to the scratch directory; false when it would leave it lexically.
bool decode(const uint8_t* data, size_t size, std::string& rel, size_t& used) {
    const size_t n_tokens = sizeof kTokens / sizeof kTokens[0];
    int depth = 0;
    used = 0;
    const size_t parts = size == 0 ? 0 : 1 + data[0] % 6;
    used = size == 0 ? 0 : 1;
    for (size_t k = 0; k < parts && used < size; ++k) {
        const uint8_t b = data[used++];
        std::string tok;
        if (b >= 240 && used < size) {
            // A raw name of up to 8 bytes (any byte but '/' and NUL).
            const size_t len = 1 + (b & 7);
            for (size_t j = 0; j < len && used < size; ++j) {
                const char c = static_cast<char>(data[used++]);
                if (c != '/' && c != '\0') tok += c;
            }
        } else {
            tok = kTokens[b % n_tokens];
        }
        if (tok == "..") {
            if (--depth < 0) return false;
        } else if (!tok.empty() && tok != ".") {
            ++depth;
        }
        rel += (k == 0 ? "" : "/") + tok;
    }
    // A trailing slash now and then.
    if (used < size && data[used] % 7 == 0) rel += "/";
    return true;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static Fixture fx;
    std::string rel;
    size_t used = 0;
    if (!decode(data, size, rel, used)) return 0;
    const std::string content(reinterpret_cast<const char*>(data) + used, size - used);
    fx.reset();
    const std::string path = fx.scratch.string() + "/" + rel;
    const auto before = snapshot(fx.scratch);

    fv::OutputTarget target;
    const std::string why = fv::resolve_output(path, target);
    const std::string err = fv::write_file_atomic(path, content);
    if (why.empty() != err.empty() && target.kind != fv::OutputTarget::Kind::special)
        broken("resolve_output and write_file_atomic disagree: '" + why + "' vs '" + err + "'", path);

    if (listing(fx.outer) != std::vector<std::string>{"s", "sentinel"})
        broken("an entry appeared or vanished outside the scratch directory", path);
    if (slurp(fx.outer / "sentinel") != "outside the scratch directory")
        broken("the file outside the scratch directory changed", path);

    const auto after = snapshot(fx.scratch);
    std::string changed;
    for (const auto& [name, v] : after) {
        if (name.find(".fv-tmp-") != std::string::npos || name.find(".fv-probe-") != std::string::npos)
            broken("a temporary file was left: " + name, path);
        const auto b = before.find(name);
        if (b == before.end() || b->second != v) {
            if (!changed.empty()) broken("more than one entry changed: " + changed + ", " + name, path);
            changed = name;
        }
    }
    for (const auto& [name, v] : before)
        if (after.find(name) == after.end()) broken("an entry vanished: " + name, path);
    if (!err.empty()) {
        if (!changed.empty()) broken("a failed write changed " + changed, path);
        return 0;
    }
    if (target.kind != fv::OutputTarget::Kind::regular) return 0;
    // The one change is the resolved target, and it holds exactly the data.
    const std::string resolved = fs::weakly_canonical(target.path).string();
    const std::string base = fs::canonical(fx.scratch).string();
    if (resolved.compare(0, base.size() + 1, base + "/") != 0)
        broken("the resolved target " + resolved + " is outside the scratch directory", path);
    if (!changed.empty() && fs::path(base) / changed != fs::path(resolved))
        broken("changed " + changed + " but the target was " + resolved, path);
    if (slurp(resolved) != content) broken("the target does not hold the data written", path);
    if (fs::is_symlink(fs::symlink_status(fx.scratch / "l")) == false) broken("link l was replaced", path);
    return 0;
}
