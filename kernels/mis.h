/* Multiple importance sampling weights (Veach 1997, ch. 9) for two strategies with one sample
 * each, given both solid-angle densities of the direction taken. */
#ifndef KERNELS_MIS_H
#define KERNELS_MIS_H
#include "single_source/vocabulary.h"

/* Power heuristic with beta = 2: a^2 / (a^2 + b^2). Written as 1 / (1 + (b/a)^2) so huge densities
 * (a sharp lobe, a sun texel) do not overflow the squares. */
SS_FN float mis_power_heuristic(float pdf_taken, float pdf_other) {
    if (!(pdf_taken > 0.0f)) return 0.0f;
    float ratio = pdf_other / pdf_taken;
    return 1.0f / (1.0f + ratio * ratio);
}

#endif
