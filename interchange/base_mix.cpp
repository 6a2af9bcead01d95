#include "interchange/base_mix.hpp"

namespace interchange {

bool split_base_mix(const brdf::Material& m, BaseMix* mix) {
    if (m.metallic > 0.0f && m.metallic < 1.0f) {
        *mix = {m.metallic, m, m};
        mix->first.metallic = 0.0f;
        mix->second.metallic = 1.0f;
        return true;
    }
    if (m.metallic == 0.0f && m.weight_transmission > 0.0f && m.weight_transmission < 1.0f) {
        *mix = {m.weight_transmission, m, m};
        mix->first.weight_transmission = 0.0f;
        mix->second.weight_transmission = 1.0f;
        return true;
    }
    return false;
}

}  // namespace interchange
