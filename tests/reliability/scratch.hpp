// A scratch directory for one test: created empty, removed with everything in it at the end.
#pragma once

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace fv::test {

inline std::string slurp(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    std::stringstream ss;
    ss << f.rdbuf();
    return ss.str();
}

class Scratch {
  public:
    Scratch() {
        char tmpl[] = "/tmp/fv-rel-XXXXXX";
        dir_ = ::mkdtemp(tmpl);
    }
    ~Scratch() {
        std::error_code ec;
        std::filesystem::remove_all(dir_, ec);
    }
    Scratch(const Scratch&) = delete;
    Scratch& operator=(const Scratch&) = delete;

    const std::string& dir() const { return dir_; }
    std::string operator/(const std::string& name) const { return dir_ + "/" + name; }

    void write(const std::string& name, const std::string& content) const {
        std::ofstream(*this / name, std::ios::binary) << content;
    }
    void mkdir(const std::string& name) const { std::filesystem::create_directory(*this / name); }
    void symlink(const std::string& to, const std::string& name) const {
        std::filesystem::create_symlink(to, *this / name);
    }
    bool is_symlink(const std::string& name) const {
        return std::filesystem::is_symlink(std::filesystem::symlink_status(*this / name));
    }
    // The names in the directory itself (hidden ones too: a left-over temporary file shows), sorted.
    std::vector<std::string> entries() const {
        std::vector<std::string> names;
        for (const auto& e : std::filesystem::directory_iterator(dir_))
            names.push_back(e.path().filename().string());
        std::sort(names.begin(), names.end());
        return names;
    }

  private:
    std::string dir_;
};

} // namespace fv::test
