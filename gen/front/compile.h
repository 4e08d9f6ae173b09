/* Compile a C source with the system compiler into a shared object and load
 * it, so that pfmathgen and pfsweep measure exactly the code that is
 * emitted, not a model of it. */
#ifndef PF_COMPILE_H
#define PF_COMPILE_H
#include <stddef.h>

/* Returns a dlopen handle or NULL with a one-line reason in err. */
void *pf_compile_load(const char *src, size_t len, char *err, size_t errlen);
void *pf_compile_load_file(const char *path, char *err, size_t errlen);

#endif
