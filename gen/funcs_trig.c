/* Function table rows for the trig family (see gen/funcs.h). */
#include "funcs.h"

const pf_spec pf_specs_trig[] = {
    {0},
};
