/* Feature switches of the BRDF module: which lobes and distributions a kernel compiles.
 * A scene's kernel defines each switch (0 or 1) before including the module, from the materials
 * it holds (brdf/host/features.hpp), and the kernel-source assembler drops the switched-off parts
 * with the files only they include. Anything not switched off is compiled, as on the host.
 * A kernel must never be handed a material that needs a switched-off feature: the host rebuilds
 * the kernel when the set of features changes. */
#ifndef BRDF_FEATURES_H
#define BRDF_FEATURES_H

#ifndef BRDF_FEATURE_LAB_MODEL
#define BRDF_FEATURE_LAB_MODEL 1 /* the default model */
#endif
#ifndef BRDF_FEATURE_DTOADQ2017
#define BRDF_FEATURE_DTOADQ2017 1 /* the 2017 formulas */
#endif
#ifndef BRDF_FEATURE_MEASURED
#define BRDF_FEATURE_MEASURED 1 /* MERL tables and their sampler (brdf/measured.h) */
#endif
#ifndef BRDF_FEATURE_OPENPBR
#define BRDF_FEATURE_OPENPBR 1 /* OpenPBR Surface's layers (brdf/openpbr_model.h) and their tables */
#endif
#ifndef BRDF_FEATURE_DIFFUSE
#define BRDF_FEATURE_DIFFUSE 1 /* Lambert (lab), energy-preserving Oren-Nayar (openpbr) */
#endif
#ifndef BRDF_FEATURE_RETROREFLECTION
#define BRDF_FEATURE_RETROREFLECTION 1 /* Disney diffuse */
#endif
#ifndef BRDF_FEATURE_SUBSURFACE
#define BRDF_FEATURE_SUBSURFACE 1 /* Henyey-Greenstein single scattering */
#endif
#ifndef BRDF_FEATURE_GLOSSY
#define BRDF_FEATURE_GLOSSY 1 /* microfacet reflection (the mirror is always there) */
#endif
#ifndef BRDF_FEATURE_TRANSMISSION
#define BRDF_FEATURE_TRANSMISSION 1 /* smooth and rough dielectric */
#endif
#ifndef BRDF_FEATURE_COAT
#define BRDF_FEATURE_COAT 1 /* openpbr: the clear coat */
#endif
#ifndef BRDF_FEATURE_FUZZ
#define BRDF_FEATURE_FUZZ 1 /* openpbr: the fuzz's sheen and its table */
#endif
#ifndef BRDF_FEATURE_THIN_FILM
#define BRDF_FEATURE_THIN_FILM 1 /* openpbr: thin-film iridescence on the dielectric specular and the metal */
#endif
#ifndef BRDF_FEATURE_EMISSION
#define BRDF_FEATURE_EMISSION 1 /* openpbr: a material's own emission (brdf/emission.h), where the integrators add it */
#endif
#ifndef BRDF_FEATURE_ENERGY_COMPENSATION
#define BRDF_FEATURE_ENERGY_COMPENSATION 1 /* Kulla-Conty multiple scattering and its tables */
#endif
#ifndef BRDF_FEATURE_GGX
#define BRDF_FEATURE_GGX 1
#endif
#ifndef BRDF_FEATURE_HYPER_CAUCHY
#define BRDF_FEATURE_HYPER_CAUCHY 1
#endif

#endif
