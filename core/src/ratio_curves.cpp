#include "fv/ratio_curves.hpp"

#include "fv/rigid.hpp"

#include <algorithm>
#include <cmath>

namespace fv {

SteadyOptions current_point_options(const RatioRequest& req) {
    SteadyOptions opt;
    opt.start = req.start;
    opt.list_states = req.model == Model::dahl;
    return opt;
}

int state_of_motion(const std::vector<SteadyState>& states, double mean_fx, double tolerance) {
    if (!std::isfinite(mean_fx)) return -1;
    int best = -1;
    double best_d = HUGE_VAL, gap = HUGE_VAL;
    for (std::size_t k = 0; k < states.size(); ++k) {
        const double d = std::abs(states[k].rx - mean_fx);
        if (d < best_d) best_d = d, best = static_cast<int>(k);
        for (std::size_t m = k + 1; m < states.size(); ++m)
            gap = std::min(gap, std::abs(states[k].rx - states[m].rx));
    }
    return best >= 0 && best_d <= std::min(tolerance, gap / 3) ? best : -1;
}

RatioJob::RatioJob(const RatioRequest& req, bool with_map, const std::optional<PanelData>& reuse) {
    out_.request = req;
    if (with_map && req.map && req.model == Model::dahl) {
        if (reuse) {
            out_.map = reuse;
        } else {
            map_spec_ = std::get<MapFigure>(map_figure(req.params.rdisp, req.params.i, req.start).content);
            map_options_ = map_options(map_spec_);
            cells_ = map_points(map_spec_);
        }
    }
}

void RatioJob::next_stage() {
    next_ = 0;
    if (stage_ == Stage::start && out_.request.model == Model::dahl)
        stage_ = Stage::curve;
    else if ((stage_ == Stage::start || stage_ == Stage::curve) && !cells_.empty())
        stage_ = Stage::map_cells;
    else if (stage_ == Stage::map_cells)
        stage_ = Stage::map_panel;
    else
        stage_ = Stage::done;
}

bool RatioJob::step() {
    const RatioRequest& req = out_.request;
    switch (stage_) {
    case Stage::start:
        out_.current = steady_ratio(req.model, req.params, current_point_options(req));
        out_.zetas = ratio_zeta_grid(req.zeta_max);
        for (double z : out_.zetas) out_.rigid_rx.push_back(rigid_ratio(z, req.params.theta).rx);
        next_stage();
        return true;
    case Stage::curve: {
        // Every point on its own, as sweep() computes it. A failed point is not drawn as if it were valid:
        // NaN leaves a gap in the curve.
        SteadyOptions opt;
        opt.record_period = false;
        opt.start = req.start;
        const Params p{out_.zetas[next_], req.params.theta, req.params.rdisp, req.params.i};
        const SteadyResult r = steady_ratio(Model::dahl, p, opt);
        const bool good = ok(shown_status(r));
        out_.model_rx.push_back(good ? r.rx : std::nan(""));
        out_.model_failed += !good;
        if (++next_ == out_.zetas.size()) next_stage();
        return true;
    }
    case Stage::map_cells: {
        SweepPoint& c = cells_[next_];
        c.result = map_cell(map_spec_, cells_, next_);
        if (++next_ == cells_.size()) next_stage();
        return true;
    }
    case Stage::map_panel:
        out_.map = map_panel_of(map_spec_, cells_, nullptr, 1);
        cells_.clear();
        next_stage();
        return true;
    case Stage::done:
        return false;
    }
    return false;
}

RatioCurves compute_ratio_curves(const RatioRequest& req, const std::function<bool()>& outdated) {
    RatioJob job(req, true);
    while (job.step())
        if (outdated && outdated()) break;
    return std::move(job.result());
}

} // namespace fv
