/* Function table rows for the atrig family (see gen/funcs.h). */
#include "funcs.h"

const pf_spec pf_specs_atrig[] = {
    {0},
};
