/* The C ABI of a dtlab predicate plug-in: a shared library that dtlab loads with
 * `--predicates plugin:PATH.so` (CLI, Python) and runs inside its one inserter like
 * a built-in backend, with or without `--perturb sos`.
 *
 * Required:
 *   int dtlab_orient3d(const double* a, const double* b, const double* c, const double* d);
 *   int dtlab_insphere(const double* a, const double* b, const double* c, const double* d,
 *                      const double* e);
 * Optional:
 *   const char* dtlab_backend_name(void);   (default: the file's name without .so)
 *
 * Each pointer names three doubles x, y, z. The result's sign is the answer (-1, 0 or +1
 * is expected; any int is read by its sign), in dtlab's convention (Shewchuk's):
 *   orient3d(a,b,c,d) > 0  iff d lies below the plane through a,b,c, where a,b,c appear
 *                          counter-clockwise seen from above: the sign of det[a-d; b-d; c-d];
 *   insphere(a,b,c,d,e) > 0 iff e lies inside the sphere through a,b,c,d when
 *                          orient3d(a,b,c,d) > 0 (the sign flips with that orientation).
 * dtlab may call the functions from several threads at once (fuzz --jobs): keep them
 * free of shared mutable state. A plug-in is loaded once per process and never unloaded.
 */
#ifndef DTLAB_PLUGIN_ABI_H
#define DTLAB_PLUGIN_ABI_H

#ifdef __cplusplus
extern "C" {
#endif

typedef int (*dtlab_orient3d_fn)(const double* a, const double* b, const double* c, const double* d);
typedef int (*dtlab_insphere_fn)(const double* a, const double* b, const double* c, const double* d,
                                 const double* e);
typedef const char* (*dtlab_backend_name_fn)(void);

int dtlab_orient3d(const double* a, const double* b, const double* c, const double* d);
int dtlab_insphere(const double* a, const double* b, const double* c, const double* d, const double* e);
const char* dtlab_backend_name(void);

#ifdef __cplusplus
}
#endif

#endif /* DTLAB_PLUGIN_ABI_H */
