#include "broadcast.hpp"

#include "fv/read_number.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace fvpy {

std::vector<py::ssize_t> broadcast_shape(const std::vector<std::pair<const char*, Doubles>>& in) {
    py::ssize_t nd = 0;
    for (const auto& a : in) nd = std::max(nd, a.second.ndim());
    std::vector<py::ssize_t> shape(static_cast<std::size_t>(nd), 1);
    for (const auto& a : in) {
        const py::ssize_t off = nd - a.second.ndim();
        for (py::ssize_t k = 0; k < a.second.ndim(); ++k) {
            const py::ssize_t n = a.second.shape(k);
            py::ssize_t& s = shape[static_cast<std::size_t>(off + k)];
            if (n == s || n == 1) continue;
            if (s != 1) {
                std::string shapes;
                for (const auto& b : in) {
                    std::string t = "(";
                    for (py::ssize_t j = 0; j < b.second.ndim(); ++j)
                        t += std::to_string(b.second.shape(j)) +
                             (b.second.ndim() == 1 || j + 1 < b.second.ndim() ? "," : "");
                    shapes += (shapes.empty() ? "" : ", ") + std::string(b.first) + " " + t + ")";
                }
                throw py::value_error("shapes do not broadcast together: " + shapes);
            }
            s = n;
        }
    }
    return shape;
}

Operand operand_of(const Doubles& a, const std::vector<py::ssize_t>& shape) {
    Operand o;
    o.data = reinterpret_cast<const char*>(a.data());
    const py::ssize_t off = static_cast<py::ssize_t>(shape.size()) - a.ndim();
    o.strides.assign(shape.size(), 0);
    for (py::ssize_t k = 0; k < a.ndim(); ++k)
        if (a.shape(k) != 1) o.strides[static_cast<std::size_t>(off + k)] = a.strides(k);
    return o;
}

double at(const Operand& o, const std::vector<py::ssize_t>& shape, py::ssize_t flat) {
    py::ssize_t offset = 0;
    for (std::size_t k = shape.size(); k-- > 0;) {
        const py::ssize_t n = shape[k];
        offset += (flat % n) * o.strides[k];
        flat /= n;
    }
    double v = 0;
    std::memcpy(&v, o.data + offset, sizeof v); // a view may be unaligned (e.g. a field of a record array)
    return v;
}

std::string index_text(const std::vector<py::ssize_t>& shape, py::ssize_t flat) {
    if (shape.empty()) return "";
    std::vector<py::ssize_t> idx(shape.size());
    for (std::size_t k = shape.size(); k-- > 0;) {
        idx[k] = flat % shape[k];
        flat /= shape[k];
    }
    std::string s = "(";
    for (std::size_t k = 0; k < idx.size(); ++k) s += (k ? ", " : "") + std::to_string(idx[k]);
    return s + (idx.size() == 1 ? ",)" : ")");
}

void check_range(const char* name, const Operand& o, const std::vector<py::ssize_t>& shape, py::ssize_t count,
                 fv::ParamRange r) {
    for (py::ssize_t k = 0; k < count; ++k) {
        const double v = at(o, shape, k);
        std::string why;
        if (!std::isfinite(v))
            why = std::string(name) + " = " +
                  (std::isnan(v) ? "nan"
                   : v > 0       ? "inf"
                                 : "-inf") +
                  " is not a finite number; allowed: " + name + " in " + fv::describe(r);
        else
            why = fv::range_message(name, v, r);
        if (why.empty()) continue;
        const std::string idx = index_text(shape, k);
        throw py::value_error(why + (idx.empty() ? "" : " (element " + idx + ")"));
    }
}

} // namespace fvpy
