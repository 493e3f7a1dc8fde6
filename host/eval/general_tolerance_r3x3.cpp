// Rule T's general mirror for rational 3 × 3 patches (eval/detail/general_tolerance_variants.h).
#define DIVISION_FIXED_RATIONAL
#define DIVISION_FIXED_DEGREE_U 3
#define DIVISION_FIXED_DEGREE_V 3
#define GENERAL_TOLERANCE_VARIANT generalTolerance_r3x3
#include "eval/detail/general_tolerance_variant.inc"
