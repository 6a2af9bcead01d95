#include "cli/report_groups.hpp"

namespace lab::cli {

std::vector<PresetGroup> group_presets(const std::vector<brdf::Preset>& presets) {
    PresetGroup conductors{"conductors", "conductors", {}};
    PresetGroup dielectrics{"dielectrics", "opaque dielectrics", {}};
    PresetGroup transmissive{"transmissive", "transmissive", {}};
    PresetGroup seed{"dtoadq2017", "the 2017 model beside the lab's dielectrics", {}};
    for (const brdf::Preset& p : presets) {
        const brdf::Material& m = p.material;
        if (m.model == BRDF_MODEL_DTOADQ2017)
            seed.presets.push_back(p);
        else if (m.weight_transmission > 0.0f && m.metallic < 1.0f)
            transmissive.presets.push_back(p);
        else if (m.metallic >= 0.5f)
            conductors.presets.push_back(p);
        else
            dielectrics.presets.push_back(p);
    }
    if (!seed.presets.empty())
        for (const brdf::Preset& p : dielectrics.presets) seed.presets.push_back(p);
    std::vector<PresetGroup> groups;
    for (PresetGroup* g : {&conductors, &dielectrics, &transmissive, &seed})
        if (!g->presets.empty()) groups.push_back(*g);
    return groups;
}

}  // namespace lab::cli
