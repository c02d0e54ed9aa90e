#include "controller/ProgressThrottle.h"

namespace airtrap {

bool ProgressThrottle::admit(Clock::time_point now) {
    if (lastDelivery_ && now - *lastDelivery_ < interval_)
        return false;
    lastDelivery_ = now;
    return true;
}

} // namespace airtrap
