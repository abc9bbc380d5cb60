// rm/quality.glsl: named presets that set the accuracy knobs together.
// Provides: RM_DRAFT, RM_INTERACTIVE, RM_FINAL, RM_REFERENCE (values for
//   RM_QUALITY), and the knob values of the chosen preset.
// Needs: nothing. Every module with knobs includes it before its defaults.
// Choose with -D RM_QUALITY=RM_FINAL (or --quality final). A knob defined on
// its own (-D RM_MAX_STEPS=300) wins over the preset. Without RM_QUALITY each
// module's own defaults apply; they equal the interactive preset.
#ifndef RM_QUALITY_GLSL
#define RM_QUALITY_GLSL

#define RM_DRAFT 1        // fastest: coarse hits, few shadow and AO samples
#define RM_INTERACTIVE 2  // the defaults: a half-pixel hit threshold
#define RM_FINAL 3        // stills: finer hits, more samples, 2 x 2 supersampling
#define RM_REFERENCE 4    // the yardstick the accuracy command measures against

#if defined(RM_QUALITY) && RM_QUALITY == RM_DRAFT
#ifndef RM_HIT_PIXELS
#define RM_HIT_PIXELS 4.0
#endif
#ifndef RM_MAX_STEPS
#define RM_MAX_STEPS 64
#endif
#ifndef RM_SHADOW_STEPS
#define RM_SHADOW_STEPS 16
#endif
#ifndef RM_AO_SAMPLES
#define RM_AO_SAMPLES 3
#endif
#elif defined(RM_QUALITY) && RM_QUALITY == RM_FINAL
#ifndef RM_HIT_PIXELS
#define RM_HIT_PIXELS 0.5
#endif
#ifndef RM_MAX_STEPS
#define RM_MAX_STEPS 400
#endif
#ifndef RM_SHADOW_STEPS
#define RM_SHADOW_STEPS 128
#endif
#ifndef RM_AO_SAMPLES
#define RM_AO_SAMPLES 8
#endif
#ifndef RM_NORMAL_TAPS
#define RM_NORMAL_TAPS 6
#endif
#ifndef RM_SAMPLES
#define RM_SAMPLES 2
#endif
#elif defined(RM_QUALITY) && RM_QUALITY == RM_REFERENCE
#ifndef RM_HIT_PIXELS
#define RM_HIT_PIXELS 0.05
#endif
#ifndef RM_HIT_EPSILON
#define RM_HIT_EPSILON 1e-6
#endif
#ifndef RM_MAX_STEPS
#define RM_MAX_STEPS 2000
#endif
#ifndef RM_SHADOW_STEPS
#define RM_SHADOW_STEPS 512
#endif
#ifndef RM_AO_SAMPLES
#define RM_AO_SAMPLES 16
#endif
#ifndef RM_NORMAL_TAPS
#define RM_NORMAL_TAPS 6
#endif
#ifndef RM_SAMPLES
#define RM_SAMPLES 4
#endif
#endif

#endif  // RM_QUALITY_GLSL
