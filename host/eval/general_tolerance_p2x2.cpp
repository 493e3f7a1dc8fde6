// Rule T's general mirror for polynomial 2 × 2 patches (eval/detail/general_tolerance_variants.h).
#define DIVISION_FIXED_POLYNOMIAL
#define DIVISION_FIXED_DEGREE_U 2
#define DIVISION_FIXED_DEGREE_V 2
#define GENERAL_TOLERANCE_VARIANT generalTolerance_p2x2
#include "eval/detail/general_tolerance_variant.inc"
