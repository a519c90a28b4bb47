// The one exception type the library throws for untrusted input (files, sizes, user
// arguments). A caller's programming error (an out-of-range id, say) is an assertion in
// debug builds and documented as undefined otherwise.
#pragma once

#include <stdexcept>
#include <string>

namespace velocity {

class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace velocity
