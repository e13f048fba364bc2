// frictionviz._core: the compiled half of the Python module (docs/python.md). It takes float64 arrays already
// broadcast by shape only (strides, no copies), checks them against the one range table (param_ranges.hpp)
// with the messages of the command line's number reader, computes with the GIL released over core's
// parallel_for, and hands back plain arrays; python/frictionviz/__init__.py makes the user-facing API of
// them.
#include "broadcast.hpp"
#include "render.hpp"

#include "fv/atomic_file.hpp"
#include "fv/fit.hpp"
#include "fv/measurements.hpp"
#include "fv/param_ranges.hpp"
#include "fv/read_number.hpp"
#include "fv/rigid.hpp"
#include "fv/steady_state.hpp"
#include "fv/sweep.hpp"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace py = pybind11;

namespace {

using fv::ParamRange;
using namespace fvpy;

// The longest status word the solver gives ("integration_failed"): the width of the status array's strings.
constexpr int kStatusChars = 18;

fv::Start start_of(const std::string& s) {
    fv::Start out = fv::Start::rest;
    if (!fv::parse_start(s, out))
        throw py::value_error("start = '" + s + "'; allowed: " + std::string(fv::kStartNames));
    return out;
}

fv::Model model_of(const std::string& s) {
    if (const auto m = fv::parse_model(s)) return *m;
    throw py::value_error("model = '" + s + "'; allowed: dahl, rigid");
}

// The options of `frictionviz ratio` and `sweep` (cli::solver_options with --scheme ode): the same options
// give the same numbers, bit for bit. list_states as there: the other start is searched too, which is part of
// `periods`.
fv::SteadyOptions options_of(double tolerance, const std::string& start) {
    if (const std::string why = fv::range_message("tolerance", tolerance, fv::kToleranceRange); !why.empty())
        throw py::value_error(why);
    fv::SteadyOptions o;
    o.scheme = fv::Scheme::ode;
    o.ode_tolerance = tolerance;
    o.start = start_of(start);
    o.list_states = true;
    return o;
}

int threads_of(int threads) {
    if (threads < 0 || threads > 256)
        throw py::value_error("threads = " + std::to_string(threads) +
                              "; allowed: threads in [1, 256], or 0 for all cores");
    return threads;
}

void put_status(std::uint32_t* cell, const std::string& s) {
    for (int c = 0; c < kStatusChars; ++c)
        cell[c] =
            c < static_cast<int>(s.size()) ? static_cast<unsigned char>(s[static_cast<std::size_t>(c)]) : 0;
}

template <class T> T* data_of(py::array& a) {
    return static_cast<T*>(a.mutable_data());
}

// ratio over broadcast arrays. rdisp and i may be None for the rigid model (which ignores them).
py::dict ratio(const std::string& model_name, const Doubles& zeta, const Doubles& theta_deg,
               const std::optional<Doubles>& rdisp, const std::optional<Doubles>& i, double tolerance,
               const std::string& start, int threads) {
    const fv::Model model = model_of(model_name);
    const fv::SteadyOptions opt = options_of(tolerance, start);
    threads = threads_of(threads);
    const bool dahl = model == fv::Model::dahl;
    if (dahl && (!rdisp || !i))
        throw py::value_error(
            std::string(!rdisp ? "rdisp" : "i") + " is required for the Dahl model; allowed: " +
            (!rdisp ? "rdisp in " + fv::describe(fv::kRdispRange) : "i in " + fv::describe(fv::kIRange)));
    std::vector<std::pair<const char*, Doubles>> in{{"zeta", zeta}, {"theta_deg", theta_deg}};
    if (rdisp) in.emplace_back("rdisp", *rdisp);
    if (i) in.emplace_back("i", *i);
    const std::vector<py::ssize_t> shape = broadcast_shape(in);
    py::ssize_t count = 1;
    for (py::ssize_t n : shape) count *= n;
    if (count > INT_MAX) throw py::value_error("more than 2147483647 points in one call; split the arrays");
    std::vector<Operand> ops;
    for (const auto& a : in) ops.push_back(operand_of(a.second, shape));
    // The same checks as the command line's flags: "theta" as --theta, in degrees. A given rdisp or i is
    // checked for the rigid model too (the command line checks a given --rdisp there as well).
    check_range("zeta", ops[0], shape, count, fv::kZetaRange);
    check_range("theta", ops[1], shape, count, fv::kThetaRange);
    if (rdisp) check_range("rdisp", ops[2], shape, count, fv::kRdispRange);
    if (i) check_range("i", ops[rdisp ? 3 : 2], shape, count, fv::kIRange);

    py::array rx(py::dtype::of<double>(), shape), ry(py::dtype::of<double>(), shape),
        err(py::dtype::of<double>(), shape), periods(py::dtype::of<std::int64_t>(), shape),
        ok(py::dtype::of<bool>(), shape),
        status(py::dtype::from_args(py::str("<U" + std::to_string(kStatusChars))), shape);
    double *prx = data_of<double>(rx), *pry = data_of<double>(ry), *perr = data_of<double>(err);
    std::int64_t* pper = data_of<std::int64_t>(periods);
    bool* pok = data_of<bool>(ok);
    std::uint32_t* pst = data_of<std::uint32_t>(status);
    {
        py::gil_scoped_release unlocked;
        // One point at a time over the threads, as `frictionviz sweep` (each point starts cold, so a value
        // never depends on its neighbours or on the thread count).
        fv::parallel_for(
            static_cast<int>(count),
            [&](int k) {
                fv::Params p;
                p.zeta = at(ops[0], shape, k);
                // As the command line converts --theta (model_options.cpp), so that the radians agree bit for
                // bit.
                p.theta = at(ops[1], shape, k) * fv::kPi / 180;
                if (dahl) {
                    p.rdisp = at(ops[2], shape, k);
                    p.i = at(ops[3], shape, k);
                }
                const fv::SteadyResult r = fv::steady_ratio(model, p, opt);
                prx[k] = r.rx;
                pry[k] = r.ry;
                perr[k] = r.error_estimate;
                pper[k] = r.periods;
                pok[k] = fv::ok(fv::reported_status(r));
                put_status(pst + static_cast<std::ptrdiff_t>(k) * kStatusChars, fv::reported_word(r));
            },
            threads);
    }
    py::dict d;
    d["r_x"] = rx;
    d["r_y"] = ry;
    d["error_estimate"] = err;
    d["periods"] = periods;
    d["status"] = status;
    d["ok"] = ok;
    return d;
}

// Eq. (9) and its y-twin over broadcast arrays (core's rigid_ratio; exact quadrature, no failures).
py::tuple rigid(const Doubles& zeta, const Doubles& theta_deg) {
    std::vector<std::pair<const char*, Doubles>> in{{"zeta", zeta}, {"theta_deg", theta_deg}};
    const std::vector<py::ssize_t> shape = broadcast_shape(in);
    py::ssize_t count = 1;
    for (py::ssize_t n : shape) count *= n;
    const Operand z = operand_of(zeta, shape), t = operand_of(theta_deg, shape);
    check_range("zeta", z, shape, count, fv::kZetaRange);
    check_range("theta", t, shape, count, fv::kThetaRange);
    py::array rx(py::dtype::of<double>(), shape), ry(py::dtype::of<double>(), shape);
    double *prx = data_of<double>(rx), *pry = data_of<double>(ry);
    {
        py::gil_scoped_release unlocked;
        for (py::ssize_t k = 0; k < count; ++k) {
            const fv::Ratio r = fv::rigid_ratio(at(z, shape, k), at(t, shape, k) * fv::kPi / 180);
            prx[k] = r.rx;
            pry[k] = r.ry;
        }
    }
    return py::make_tuple(rx, ry);
}

void check_scalar(const char* name, double v, ParamRange r) {
    const Doubles a(std::vector<py::ssize_t>{}, &v);
    check_range(name, operand_of(a, {}), {}, 1, r);
}

// One steady period of the Dahl model, as `frictionviz trace` (1024 samples of the ode scheme).
py::dict trace(double zeta, double theta_deg, double rdisp, double i, double tolerance,
               const std::string& start) {
    check_scalar("zeta", zeta, fv::kZetaRange);
    check_scalar("theta", theta_deg, fv::kThetaRange);
    check_scalar("rdisp", rdisp, fv::kRdispRange);
    check_scalar("i", i, fv::kIRange);
    fv::SteadyOptions o = options_of(tolerance, start);
    o.record_period = true;
    fv::Params p;
    p.zeta = zeta;
    p.theta = theta_deg * fv::kPi / 180;
    p.rdisp = rdisp;
    p.i = i;
    fv::SteadyResult r;
    {
        py::gil_scoped_release unlocked;
        r = fv::steady_ratio(fv::Model::dahl, p, o);
    }
    const auto n = static_cast<py::ssize_t>(r.period.size());
    py::array_t<double> tau(n), px(n), py_(n), tx(n), ty(n), z(n), fx(n), fy(n);
    py::array_t<bool> stick(n);
    bool finite = true;
    const double zss = p.zss();
    for (py::ssize_t k = 0; k < n; ++k) {
        const fv::Sample& s = r.period[static_cast<std::size_t>(k)];
        tau.mutable_at(k) = s.tau;
        px.mutable_at(k) = s.P.x();
        py_.mutable_at(k) = s.P.y();
        tx.mutable_at(k) = s.T.x();
        ty.mutable_at(k) = s.T.y();
        z.mutable_at(k) = s.z;
        fx.mutable_at(k) = s.F.x();
        fy.mutable_at(k) = s.F.y();
        for (double v : {s.tau, s.P.x(), s.P.y(), s.T.x(), s.T.y(), s.z, s.F.x(), s.F.y()})
            finite = finite && std::isfinite(v);
        // Stuck: the tip T did not move since the previous sample (the period wraps around). Its position is
        // held exactly while it sticks, so the comparison needs only a rounding margin relative to z_ss.
        const fv::Sample& prev = r.period[static_cast<std::size_t>(k == 0 ? n - 1 : k - 1)];
        stick.mutable_at(k) = k > 0 && (s.T - prev.T).norm() <= 1e-12 * zss;
    }
    if (n > 1) stick.mutable_at(0) = stick.at(1) && stick.at(n - 1);
    // As `frictionviz trace`: a verified steady state with a value that is not finite is non_finite.
    std::string st = fv::reported_word(r);
    if (fv::ok(r.status) && !finite) st = fv::to_string(fv::SteadyStatus::non_finite);
    py::dict d;
    d["tau"] = tau;
    d["Px"] = px;
    d["Py"] = py_;
    d["Tx"] = tx;
    d["Ty"] = ty;
    d["z"] = z;
    d["Fx"] = fx;
    d["Fy"] = fy;
    d["stick"] = stick;
    d["r_x"] = r.rx;
    d["r_y"] = r.ry;
    d["error_estimate"] = r.error_estimate;
    d["periods"] = r.periods;
    d["status"] = st;
    return d;
}

py::dict measurements_dict(const fv::MeasurementSet& m) {
    const auto n = static_cast<py::ssize_t>(m.points.size());
    py::array_t<double> zeta(n), rx(n), theta(n), sigma(n), vb(n);
    py::array_t<std::int64_t> line(n);
    py::list labels;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (py::ssize_t k = 0; k < n; ++k) {
        const fv::Measurement& x = m.points[static_cast<std::size_t>(k)];
        zeta.mutable_at(k) = x.zeta;
        rx.mutable_at(k) = x.rx;
        theta.mutable_at(k) = x.theta_deg.value_or(nan);
        sigma.mutable_at(k) = x.sigma.value_or(nan);
        vb.mutable_at(k) = x.vb.value_or(nan);
        line.mutable_at(k) = x.line;
        labels.append(x.label);
    }
    py::dict d;
    d["file"] = m.file;
    d["zeta"] = zeta;
    d["r_x"] = rx;
    d["theta_deg"] = m.has_theta ? py::object(theta) : py::object(py::none());
    d["sigma"] = m.has_sigma ? py::object(sigma) : py::object(py::none());
    d["vb"] = m.from_vb ? py::object(vb) : py::object(py::none());
    d["label"] = labels;
    d["line"] = line;
    d["synthetic"] = m.synthetic;
    return d;
}

fv::ReadOptions read_options(std::optional<double> amplitude_um, std::optional<double> frequency_khz) {
    fv::ReadOptions ro;
    if (amplitude_um) check_scalar("amplitude_um", *amplitude_um, fv::kAmplitudeRange);
    if (frequency_khz) check_scalar("frequency_khz", *frequency_khz, fv::kFrequencyRange);
    ro.amplitude_um = amplitude_um;
    ro.frequency_khz = frequency_khz;
    return ro;
}

// The file's errors are ValueError with the command line's text ("FILE:LINE:COL: message").
py::dict read_file(const std::string& path, std::optional<double> amplitude_um,
                   std::optional<double> frequency_khz) {
    try {
        return measurements_dict(fv::read_measurements(path, read_options(amplitude_um, frequency_khz)));
    } catch (const fv::DataError& e) {
        throw py::value_error(e.what());
    }
}

py::dict candidate_dict(const fv::FitCandidate& c) {
    py::dict d;
    d["i"] = c.i;
    d["rdisp"] = c.rdisp;
    d["rdisp_sigma"] = c.rdisp_sigma;
    d["log_rdisp_sigma"] = c.log_rdisp_sigma;
    d["weighted"] = c.weighted;
    d["chi2"] = c.chi2;
    d["dof"] = c.dof;
    d["reduced_chi2"] = c.reduced_chi2;
    d["aic"] = c.aic;
    d["model"] = py::array_t<double>(static_cast<py::ssize_t>(c.model.size()), c.model.data());
    d["residuals"] = py::array_t<double>(static_cast<py::ssize_t>(c.residuals.size()), c.residuals.data());
    d["zss_um"] = c.zss_um ? py::object(py::float_(*c.zss_um)) : py::object(py::none());
    d["zss_um_sigma"] = c.zss_um_sigma ? py::object(py::float_(*c.zss_um_sigma)) : py::object(py::none());
    d["at_bound"] = c.at_bound;
    d["converged"] = c.converged;
    d["evaluations"] = c.evaluations;
    d["unsteady"] = c.unsteady;
    return d;
}

// fit_rdisp on a file (read as `frictionviz fit --data` reads it) or on arrays (checked as the file's fields
// are: the same ranges).
py::dict fit(const std::optional<std::string>& path, const std::optional<Doubles>& zeta,
             const std::optional<Doubles>& rx, const std::optional<Doubles>& theta_col,
             const std::optional<Doubles>& sigma, std::optional<double> theta_deg, const std::string& shape,
             std::optional<double> amplitude_um, std::optional<double> frequency_khz, int threads) {
    fv::FitOptions fo;
    fo.threads = threads_of(threads);
    if (theta_deg) check_scalar("theta", *theta_deg, fv::kThetaRange);
    fo.theta_deg = theta_deg;
    fo.amplitude_um = amplitude_um;
    if (shape == "0")
        fo.shape = fv::ShapeChoice::i0;
    else if (shape == "1")
        fo.shape = fv::ShapeChoice::i1;
    else if (shape == "auto")
        fo.shape = fv::ShapeChoice::automatic;
    else
        throw py::value_error("i = '" + shape + "'; allowed: 0, 1, or 'auto'");
    fv::MeasurementSet data;
    if (path) {
        data = fv::read_measurements(*path, read_options(amplitude_um, frequency_khz));
    } else {
        read_options(amplitude_um, frequency_khz);
        const auto n = zeta->size();
        if (rx->size() != n || (theta_col && theta_col->size() != n) || (sigma && sigma->size() != n))
            throw py::value_error("zeta, r_x, theta_deg and sigma must have the same length");
        const Doubles flat[4] = {*zeta, *rx, theta_col ? *theta_col : *zeta, sigma ? *sigma : *zeta};
        const std::vector<py::ssize_t> shape1{static_cast<py::ssize_t>(n)};
        check_range("zeta", operand_of(flat[0], shape1), shape1, n, fv::kZetaRange);
        check_range("r_x", operand_of(flat[1], shape1), shape1, n, fv::kRxDataRange);
        if (theta_col) check_range("theta_deg", operand_of(flat[2], shape1), shape1, n, fv::kThetaRange);
        if (sigma) check_range("sigma", operand_of(flat[3], shape1), shape1, n, fv::kSigmaRange);
        data.file = "<arrays>";
        data.has_theta = theta_col.has_value();
        data.has_sigma = sigma.has_value();
        for (py::ssize_t k = 0; k < n; ++k) {
            fv::Measurement m;
            m.zeta = flat[0].at(k);
            m.rx = flat[1].at(k);
            if (theta_col) m.theta_deg = flat[2].at(k);
            if (sigma) m.sigma = flat[3].at(k);
            m.line = static_cast<int>(k + 1);
            data.points.push_back(m);
        }
    }
    if (!data.has_theta && !fo.theta_deg)
        throw py::value_error("theta_deg is required: " + data.file + " has no theta_deg column");
    fv::FitResult r;
    {
        py::gil_scoped_release unlocked;
        r = fv::fit_rdisp(data, fo);
    }
    py::dict d;
    d["best"] = candidate_dict(r.best);
    py::list cands;
    for (const fv::FitCandidate& c : r.candidates) cands.append(candidate_dict(c));
    d["candidates"] = cands;
    std::string why;
    const std::string st = fv::to_string(fv::fit_status(r, why));
    d["status"] = st;
    d["detail"] = why;
    d["file"] = data.file;
    return d;
}

// Writes `data` to `path` by the output-path policy of every file the program writes (fv/atomic_file.hpp):
// atomic, nothing half-written, links followed; OSError with the one-line reason otherwise.
void write_file(const std::string& path, const py::bytes& data) {
    const std::string content = data;
    std::string why;
    {
        py::gil_scoped_release unlocked;
        why = fv::write_file_atomic(path, content);
    }
    if (!why.empty()) throw py::value_error(why); // replaced by OSError in __init__.py
}

} // namespace

PYBIND11_MODULE(_core, m) {
    m.doc() = "frictionviz's compiled core; use the package `frictionviz`, not this module";
    py::register_exception<fv::DataError>(m, "DataError", PyExc_ValueError);
    py::register_exception<fv::FitError>(m, "FitError", PyExc_ValueError);
    m.def("ratio", &ratio, py::arg("model"), py::arg("zeta"), py::arg("theta_deg"),
          py::arg("rdisp").none(true), py::arg("i").none(true), py::arg("tolerance"), py::arg("start"),
          py::arg("threads"));
    m.def("rigid_ratio", &rigid, py::arg("zeta"), py::arg("theta_deg"));
    m.def("trace", &trace, py::arg("zeta"), py::arg("theta_deg"), py::arg("rdisp"), py::arg("i"),
          py::arg("tolerance"), py::arg("start"));
    m.def("read_measurements", &read_file, py::arg("path"), py::arg("amplitude_um").none(true),
          py::arg("frequency_khz").none(true));
    m.def("fit", &fit, py::arg("path").none(true), py::arg("zeta").none(true), py::arg("r_x").none(true),
          py::arg("theta_col").none(true), py::arg("sigma").none(true), py::arg("theta_deg").none(true),
          py::arg("shape"), py::arg("amplitude_um").none(true), py::arg("frequency_khz").none(true),
          py::arg("threads"));
    m.def("figures", &fvpy::figures);
    m.def("render", &fvpy::render, py::arg("spec"), py::arg("example"), py::arg("width"), py::arg("height"),
          py::arg("scale"), py::arg("format"));
    m.def("write_file", &write_file, py::arg("path"), py::arg("data"));
    m.attr("default_tolerance") = fv::SteadyOptions{}.ode_tolerance;
}
