#include "texture_params.hpp"

namespace rtlab::detail {

ColorEncoding get_encoding(const Params& params) {
    return one_of(params, "encoding", "srgb", {"srgb", "linear"}) == "srgb" ? ColorEncoding::srgb
                                                                            : ColorEncoding::linear;
}

}  // namespace rtlab::detail
