#pragma once
/// \brief The one exception type rtlab throws for bad input and failed I/O.
#include <stdexcept>
#include <string>

namespace rtlab {

/// \brief A user-facing error: the message names the file, element or parameter and the problem.
class Error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace rtlab
