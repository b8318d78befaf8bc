// GSL's default error handler aborts on a non-finite function value; the calibration searches
// (log_search, root_search) check GSL's status codes instead. Switched off for the scope and
// restored on the way out, also when an objective (a simulation) throws.
#pragma once
#include <gsl/gsl_errno.h>

namespace kolsky::harness {

struct GslHandlerOff {
  gsl_error_handler_t* previous = gsl_set_error_handler_off();
  GslHandlerOff() = default;
  GslHandlerOff(const GslHandlerOff&) = delete;
  GslHandlerOff& operator=(const GslHandlerOff&) = delete;
  ~GslHandlerOff() { gsl_set_error_handler(previous); }
};

}  // namespace kolsky::harness
