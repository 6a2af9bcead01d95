// The viewer's "save EXR" (the view menu's button, --save-exr): the frame shown (A's image,
// linear) with the AOV layers chosen, named as `render --aov` names them (render/aov_layers), and
// a tone-mapped PNG beside it. The first-hit layers are the views' (over kViewFirstHitSamples
// samples), the variance and samples layers the film's at the frame; the file holds no film (the
// viewer's render is not a part to merge or resume).
#pragma once

#include <string>

#include "film/tone_map.hpp"
#include "render/aov_layers.hpp"
#include "viewer/render_worker.hpp"

namespace lab::viewer {

// Whether `frame` holds every layer `selection` chooses (the worker publishes them only while
// asked: RenderWorker::want_views).
bool frame_has_layers(const RenderFrame& frame, const render::AovSelection& selection);

// Writes the EXR and the PNG; throws lab::InputError naming `path` when the frame lacks a chosen
// layer (not published yet) or the files cannot be written.
void save_frame_exr(const std::string& path, const RenderFrame& frame, const render::AovSelection& selection, film::ToneMap tone_map,
                    float exposure_stops);

}  // namespace lab::viewer
