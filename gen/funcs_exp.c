/* Function table rows for the exp family (see gen/funcs.h). */
#include "funcs.h"

const pf_spec pf_specs_exp[] = {
    {0},
};
