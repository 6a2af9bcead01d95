#include "bench/march_cost.hpp"

#include "render/opencl_renderer.hpp"

namespace lab::bench {

MarchCost measure_march_cost(const opencl::Runtime& runtime, render::RenderInput input, int samples) {
    render::OpenClRenderer plain(runtime, input);
    plain.add_samples(samples);
    render::RenderStatistics p = plain.statistics();
    input.settings.opencl.extra_build_options += " -DSCENE_COUNT_EVALUATIONS";
    input.settings.opencl.packets = false;  // the counting build marches every ray in its path's work-item
    render::OpenClRenderer counting(runtime, input);
    counting.add_samples(samples);
    render::RenderStatistics c = counting.statistics();  // rays: march steps; lost rays: evaluations
    MarchCost w;
    render::FilmReadback a = plain.film(), b = counting.film();
    w.same_film = a.accumulation == b.accumulation && a.splat == b.splat;
    w.rays_per_path = p.paths ? double(p.rays) / double(p.paths) : 0.0;
    w.steps_per_ray = p.rays ? double(c.rays) / double(p.rays) : 0.0;
    w.evaluations_per_step = c.rays ? double(c.lost_rays) / double(c.rays) : 0.0;
    return w;
}

}  // namespace lab::bench
