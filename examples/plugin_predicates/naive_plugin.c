/* A dtlab predicate plug-in (predicates/plugin_abi.h): the plain double determinants,
 * written as dtlab's built-in `naive` backend evaluates them (same differences, same
 * cofactor order), so it makes the same decisions bit for bit.
 *   cc -O2 -shared -fPIC -ffp-contract=off -I<dtlab>/predicates naive_plugin.c -o naive_plugin.so
 *   dtlab tetra pts.xyz --predicates plugin:./naive_plugin.so
 */
#include "plugin_abi.h"

static int sign(double v) { return (v > 0) - (v < 0); }

int dtlab_orient3d(const double* a, const double* b, const double* c, const double* d) {
  const double adx = a[0] - d[0], ady = a[1] - d[1], adz = a[2] - d[2];
  const double bdx = b[0] - d[0], bdy = b[1] - d[1], bdz = b[2] - d[2];
  const double cdx = c[0] - d[0], cdy = c[1] - d[1], cdz = c[2] - d[2];
  return sign(adx * (bdy * cdz - bdz * cdy) + bdx * (cdy * adz - cdz * ady) + cdx * (ady * bdz - adz * bdy));
}

int dtlab_insphere(const double* a, const double* b, const double* c, const double* d, const double* e) {
  const double aex = a[0] - e[0], aey = a[1] - e[1], aez = a[2] - e[2];
  const double bex = b[0] - e[0], bey = b[1] - e[1], bez = b[2] - e[2];
  const double cex = c[0] - e[0], cey = c[1] - e[1], cez = c[2] - e[2];
  const double dex = d[0] - e[0], dey = d[1] - e[1], dez = d[2] - e[2];
  const double ab = aex * bey - bex * aey, bc = bex * cey - cex * bey;
  const double cd = cex * dey - dex * cey, da = dex * aey - aex * dey;
  const double ac = aex * cey - cex * aey, bd = bex * dey - dex * bey;
  const double abc = aez * bc - bez * ac + cez * ab;
  const double bcd = bez * cd - cez * bd + dez * bc;
  const double cda = cez * da + dez * ac + aez * cd;
  const double dab = dez * ab + aez * bd + bez * da;
  const double alift = aex * aex + aey * aey + aez * aez;
  const double blift = bex * bex + bey * bey + bez * bez;
  const double clift = cex * cex + cey * cey + cez * cez;
  const double dlift = dex * dex + dey * dey + dez * dez;
  return sign((dlift * abc - clift * dab) + (blift * cda - alift * bcd));
}

const char* dtlab_backend_name(void) { return "plugin-naive"; }
