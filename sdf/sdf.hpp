// The single-source SDF library compiled as C++ for the host: namespace sdf.
//
// Primitives, their exact ray intersections (sdf/exact/), domain operators, combinators and
// Lipschitz bounds are here. The marcher and the normals (sdf/march.h, sdf/normals.h) call the
// scene's `scene_march_distance` (the field the march sees), `scene_distance` and
// `scene_analytic_normal`, which must be declared before them, so they are NOT included here:
// a host translation unit that marches declares its scene in a namespace of its own and includes
// them after it:
//
//     #include "sdf/sdf.hpp"
//     namespace my_scene {            // one namespace per scene (the headers have include guards,
//     using namespace sdf;            // so one scene per translation unit; a scene that dispatches
//     inline float scene_distance(float3 p) { return fSphere(p, 1.0f); }   // at run time can
//     inline float scene_march_distance(float3 p) { return scene_distance(p); }
//     inline int scene_analytic_normal(float3 p, float3* n) {              // serve several)
//         *n = nSphere(p, 1.0f);
//         return 1;
//     }
//     #include "sdf/march.h"
//     #include "sdf/normals.h"
//     }  // namespace my_scene
//
// Give that namespace a name no other translation unit uses, since march() and the normals are
// inline functions and the same qualified name must not mean two scenes (one definition rule).
#pragma once

// The vocabulary (float3, sqr, float3_splat, max_component, SS_FN) lives in namespace
// single_source; its include guard makes the includes below see it through the using-directive.
#include "single_source/host_vocabulary.hpp"

namespace sdf {
using namespace single_source;
#include "sdf/lipschitz.h"
#include "sdf/primitives/box.h"
#include "sdf/primitives/capsule.h"
#include "sdf/primitives/cone.h"
#include "sdf/primitives/cylinder.h"
#include "sdf/primitives/disk.h"
#include "sdf/primitives/plane.h"
#include "sdf/primitives/rect.h"
#include "sdf/primitives/round_box.h"
#include "sdf/primitives/sphere.h"
#include "sdf/primitives/torus.h"
#include "sdf/exact/box.h"
#include "sdf/exact/capsule.h"
#include "sdf/exact/cone.h"
#include "sdf/exact/cylinder.h"
#include "sdf/exact/disk.h"
#include "sdf/exact/plane.h"
#include "sdf/exact/rect.h"
#include "sdf/exact/round_box.h"
#include "sdf/exact/sphere.h"
#include "sdf/exact/torus.h"
#include "sdf/domain/mirror.h"
#include "sdf/domain/mod3.h"
#include "sdf/domain/mod_interval3.h"
#include "sdf/combinators/displace_sine.h"
#include "sdf/combinators/intersection.h"
#include "sdf/combinators/intersection_chamfer.h"
#include "sdf/combinators/intersection_round.h"
#include "sdf/combinators/subtraction.h"
#include "sdf/combinators/subtraction_chamfer.h"
#include "sdf/combinators/subtraction_round.h"
#include "sdf/combinators/union.h"
#include "sdf/combinators/union_chamfer.h"
#include "sdf/combinators/union_round.h"
#include "sdf/combinators/union_smooth.h"
}  // namespace sdf
