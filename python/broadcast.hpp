// Broadcasting for frictionviz._core (module.cpp): numpy's rule over float64 operands read in place by their
// strides (no copy beyond the one conversion to float64 that py::array_t's forcecast makes), and the range
// checks with the command line's messages and the failing element's index.
#pragma once

#include "fv/param_ranges.hpp"

#include <pybind11/numpy.h>

#include <string>
#include <utility>
#include <vector>

namespace fvpy {

namespace py = pybind11;

using Doubles = py::array_t<double, py::array::forcecast>;

// One input of a broadcast: its data and, per axis of the common shape, the byte stride (0 along an axis the
// input broadcasts over).
struct Operand {
    const char* data = nullptr;
    std::vector<py::ssize_t> strides;
};

// The common shape of the operands (numpy's rule: axes aligned at the right, each of length 1 or the common
// one). Throws ValueError naming the shapes otherwise.
std::vector<py::ssize_t> broadcast_shape(const std::vector<std::pair<const char*, Doubles>>& in);

// `a` read as an operand of `shape` (its strides, 0 along broadcast axes).
Operand operand_of(const Doubles& a, const std::vector<py::ssize_t>& shape);

// The element of `o` at the flat (C-order) index `flat` of `shape`.
double at(const Operand& o, const std::vector<py::ssize_t>& shape, py::ssize_t flat);

// "(1, 2)" for element 5 of shape (2, 3); "" for a 0-d array.
std::string index_text(const std::vector<py::ssize_t>& shape, py::ssize_t flat);

// The command line's message for a number out of its range (read_number.hpp: "zeta = 200 is out of range;
// allowed: zeta in [0, 100]"), with the element's index for arrays: ValueError. NaN and infinities are
// refused as the command line refuses the texts "nan" and "inf".
void check_range(const char* name, const Operand& o, const std::vector<py::ssize_t>& shape, py::ssize_t count,
                 fv::ParamRange r);

} // namespace fvpy
