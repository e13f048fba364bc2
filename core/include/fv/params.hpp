// The four numbers every result depends on (docs/model.md, "Parameters").
#pragma once

#include <optional>
#include <string>

namespace fv {

inline constexpr double kPi = 3.14159265358979323846;

// Which friction law is used between body point P and asperity tip T.
enum class Model {
    rigid, // Coulomb friction on a rigid body, Eqs. (1)-(11)
    dahl,  // lumped compliant asperity, Eqs. (12)-(34)
};

const char* to_string(Model m);
std::optional<Model> parse_model(const std::string& s);

// Dimensionless parameters.
//   zeta  = v_b / v_v            velocity ratio, Eq. (6)
//   theta = vibration angle to v_b, radians, Eq. (1)
//   rdisp = x_v / z_ss           displacement ratio, Eq. (34); z_ss = 1/rdisp in units of x_v
//   i     = Dahl shape exponent, Eq. (12); any real i >= 0 (i = 0 is the stiction model of Eq. (27))
struct Params {
    double zeta = 0.5;
    double theta = kPi / 2;
    double rdisp = 2.0;
    double i = 1.0;

    double zss() const { return 1.0 / rdisp; }
};

// Empty when the parameters are admissible, else a one-line reason naming the parameter and the allowed
// range.
std::string validate(const Params& p);

} // namespace fv
