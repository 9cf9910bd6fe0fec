#include "budget_controller.h"

#include <algorithm>
#include <cmath>

namespace retroaa {

double BudgetController::update(double measuredMs) {
  if (!(measuredMs >= 0) || !std::isfinite(measuredMs) || budgetMs_ <= 0) return scale_;
  smoothedMs_ = smoothedMs_ < 0 ? measuredMs : 0.5 * smoothedMs_ + 0.5 * measuredMs;
  const double error = (budgetMs_ - smoothedMs_) / budgetMs_;  // > 0: room to spend
  if (std::fabs(error) > 0.05) {
    const double step = std::clamp(error, -0.2, 0.2);  // at most ±20 % per frame
    scale_ = std::clamp(scale_ * std::exp(step), kMinScale, kMaxScale);
  }
  return scale_;
}

}  // namespace retroaa
