// The first limit point of a followed path: a maximum of the load factor from which the path
// then falls by more than limit_drop of its rise in the stage. The load there is the structure's
// capacity. A higher load met later on the same path (a column folded far past its peak that
// stiffens as it folds on, an arch inverted after its snap-through) belongs to another branch
// and is never reported as the peak (Crisfield, Non-linear Finite Element Analysis of Solids and
// Structures, vol. 1, 1991, §9: the limit point is where the load's path parameter derivative
// changes sign).
#pragma once

namespace plastica {

class PathWatch {
public:
    // A larger drop than a node-by-node contact's sawtooth (2.4 % on a ring between plates).
    static constexpr double limit_drop = 0.05;

    // A stage begins at load factor λ. watched: its λ is a load (not the travel of a plate
    // alone) and it loads (not a stage that unloads by design), in the direction `direction` (±1).
    void begin_stage(bool watched, double direction, double lambda);
    // A converged step.
    void note(int step, double lambda);
    // Whether the path has passed its first limit point (in any stage so far), where, and at
    // which load factor.
    bool past_first_limit() const { return limit_step_ >= 0; }
    int limit_step() const { return limit_step_; }
    double limit_load_factor() const { return limit_lambda_; }

private:
    bool watched_ = false;
    double direction_ = 1.0;
    double lambda_start_ = 0.0;
    double rise_ = 0.0; // the largest rise of λ in the stage's direction, at rise_step_
    int rise_step_ = 0;
    double rise_lambda_ = 0.0;
    int limit_step_ = -1;
    double limit_lambda_ = 0.0;
};

} // namespace plastica
