/* What the camera-march packet kernel (kernels/camera_march.cl) hands the path tracer: for each
 * pixel of a launch, the march of its camera ray for the launch's one sample (kernels/path.h,
 * trace_camera_ray). */
#ifndef KERNELS_CAMERA_MARCH_H
#define KERNELS_CAMERA_MARCH_H

#include "single_source/vocabulary.h"

typedef struct CameraMarch {
    float t;    /* sdf/march_lanes.h's MarchLanes, one lane */
    int status;
    int steps;
} CameraMarch;

#endif
