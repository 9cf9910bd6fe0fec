// Frame-time budget for the techniques that follow it (Technique::followsBudget): a damped integral controller
// on the log of a quality scale that multiplies the refinement metrics, fed the plugin's measured GPU
// time each frame it has (the frame statistics come back a frame or two late, without a wait).
//
// Damping: the measurement is smoothed exponentially (α = 0.5) so one noisy frame moves little; the
// scale changes by at most ±gain·20 % of itself per frame; inside a ±5 % band around the budget it holds
// still, so a met budget does not dither. More scale → more samples → more time (monotonic), which
// makes the integral converge without overshoot for gains ≤ 1 on the costs measured here.
#pragma once

namespace retroaa {

class BudgetController {
 public:
  static constexpr double kMinScale = 0.02, kMaxScale = 50.0;
  explicit BudgetController(double budgetMs) : budgetMs_(budgetMs) {}
  // The plugin's GPU time of the newest measured frame; returns the scale for the next one.
  double update(double measuredMs);
  double scale() const { return scale_; }

 private:
  double budgetMs_;
  double scale_ = 1.0;
  double smoothedMs_ = -1.0;
};

}  // namespace retroaa
