// Private: the tolerances and work budgets of the library's inside, with their
// units. What a user can see (input limits, the curve bound, defaults of
// documented behaviour) is in the public curvetext/tolerances.hpp, which this
// header includes, so code that needs both includes this one.
#pragma once

#include <cstddef>

#include "curvetext/tolerances.hpp"
