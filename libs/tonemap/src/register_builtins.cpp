#include <rtlab/tonemap/tone_operator.hpp>

namespace rtlab {

namespace tonemap {
void register_ward(ToneRegistry& r);
void register_reinhard(ToneRegistry& r);
void register_exposure(ToneRegistry& r);
}  // namespace tonemap

void register_builtins(ToneRegistry& registry) {
    tonemap::register_ward(registry);
    tonemap::register_reinhard(registry);
    tonemap::register_exposure(registry);
}

ToneRegistry make_tone_registry() {
    ToneRegistry r("tone operator");
    register_builtins(r);
    return r;
}

}  // namespace rtlab
