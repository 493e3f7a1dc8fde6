// Rule T's general mirror for rational 1 × 2 patches (eval/detail/general_tolerance_variants.h).
#define DIVISION_FIXED_RATIONAL
#define DIVISION_FIXED_DEGREE_U 1
#define DIVISION_FIXED_DEGREE_V 2
#define GENERAL_TOLERANCE_VARIANT generalTolerance_r1x2
#include "eval/detail/general_tolerance_variant.inc"
