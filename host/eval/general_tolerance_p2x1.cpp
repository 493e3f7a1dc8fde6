// Rule T's general mirror for polynomial 2 × 1 patches (eval/detail/general_tolerance_variants.h).
#define DIVISION_FIXED_POLYNOMIAL
#define DIVISION_FIXED_DEGREE_U 2
#define DIVISION_FIXED_DEGREE_V 1
#define GENERAL_TOLERANCE_VARIANT generalTolerance_p2x1
#include "eval/detail/general_tolerance_variant.inc"
