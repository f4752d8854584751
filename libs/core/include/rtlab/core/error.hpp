#pragma once
/// \brief The exception types rtlab throws for bad input and failed I/O.
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace rtlab {

/// \brief A user-facing error: the message names the file, element or parameter and the problem.
class Error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// \brief An error about named parameters of an object built from Params: a scene loader reports it at each
/// key's own position without reading the message text.
class ParamError : public Error {
public:
    enum class Reason {
        invalid,  ///< the value of keys()[0] is wrong (or missing)
        unused,   ///< keys() were given but the type takes no such parameters
    };

    ParamError(const std::string& message, std::vector<std::string> keys, Reason reason = Reason::invalid)
        : Error(message), m_keys(std::move(keys)), m_reason(reason) {}

    const std::vector<std::string>& keys() const { return m_keys; }
    Reason reason() const { return m_reason; }

private:
    std::vector<std::string> m_keys;
    Reason m_reason;
};

}  // namespace rtlab
