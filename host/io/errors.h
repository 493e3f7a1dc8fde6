// The one exception type for bad input and failed file I/O: InputError (with its kind, file,
// line and reason) lives in the public header include/tessera/errors.h, so callers of the
// library catch the very type the readers throw. Every reader and the atomic writer throw it;
// the CLI prints what() as-is and tests check the kind, file and line apart from the wording.
#pragma once
#include "tessera/errors.h"
