// A running worst difference in which a NaN is the worst of all. std::max passes a NaN over (NaN < x
// is false), so a kernel or an estimate that returned NaN would read as perfect agreement.
#pragma once

#include <cmath>

inline double worse_of(double worst, double difference) {
    return std::isnan(worst) || difference <= worst ? worst : difference;
}
