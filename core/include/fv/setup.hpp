// One setup of the model: the friction law, its four parameters and the start (the history that picks between
// coexisting steady states). The app shows setup A and, in compare mode, setup B beside it: two values of
// this type run by the same code (the app's state, its share link, sessions, lessons, `animate --view
// compare`).
#pragma once

#include "fv/params.hpp"
#include "fv/steady_state.hpp" // Start

namespace fv {

struct Setup {
    Model model = Model::dahl;
    Params params{0.15, kPi / 2, 2, 1};
    Start start = Start::rest;
    bool operator==(const Setup& o) const {
        return model == o.model && params.zeta == o.params.zeta && params.theta == o.params.theta &&
               params.rdisp == o.params.rdisp && params.i == o.params.i && start == o.start;
    }
    bool operator!=(const Setup& o) const { return !(*this == o); }
};

// The setup B that compare mode starts from beside `a`: the same model, parameters and start at the other of
// the two angles a teacher compares, theta = 90 degrees (across the motion) unless a is at 90 degrees
// already, then theta = 0 (along it).
Setup compare_default(const Setup& a);

} // namespace fv
