/* A dtlab predicate plug-in with exact signs: both determinants in GMP rationals
 * (every finite double is a rational, mpq_set_d converts it exactly). Slow (about a
 * microsecond per call) and simple: the kind of reference a new filter is checked
 * against.
 *   cc -O2 -shared -fPIC -I<dtlab>/predicates exact_plugin.c -o exact_plugin.so -lgmp
 */
#include <gmp.h>

#include "plugin_abi.h"

/* out = the 3x3 determinant of rows r[0], r[1], r[2] (r[i] = 3 rationals). */
static void det3(mpq_t out, mpq_t r[3][3], mpq_t t, mpq_t u) {
  mpq_set_ui(out, 0, 1);
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    mpq_mul(t, r[1][j], r[2][k]);
    mpq_mul(u, r[1][k], r[2][j]);
    mpq_sub(t, t, u);
    mpq_mul(t, t, r[0][i]);
    mpq_add(out, out, t);
  }
}

/* The sign of det[p[0]-q; p[1]-q; p[2]-q] (count 3, no lift) or of the lifted 4x4
 * determinant of p[0..3] - q with |p-q|^2 as the last column (count 4). */
static int lifted_sign(const double* const* p, int count, const double* q) {
  mpq_t m[4][4], t, u, v, det, minor[3][3];
  mpq_inits(t, u, v, det, NULL);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) mpq_init(m[i][j]);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) mpq_init(minor[i][j]);
  for (int i = 0; i < count; ++i) {
    mpq_set_ui(m[i][3], 0, 1);
    for (int j = 0; j < 3; ++j) {
      mpq_set_d(t, p[i][j]);
      mpq_set_d(u, q[j]);
      mpq_sub(m[i][j], t, u);
      mpq_mul(t, m[i][j], m[i][j]);
      mpq_add(m[i][3], m[i][3], t);
    }
  }
  if (count == 3) {
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) mpq_set(minor[i][j], m[i][j]);
    det3(det, minor, t, u);
  } else {
    /* Expansion along the lift column: sum over rows i of (-1)^(i+3) lift_i M_i3. */
    mpq_set_ui(det, 0, 1);
    for (int i = 0; i < 4; ++i) {
      for (int r = 0, k = 0; r < 4; ++r)
        if (r != i) {
          for (int j = 0; j < 3; ++j) mpq_set(minor[k][j], m[r][j]);
          ++k;
        }
      det3(v, minor, t, u);
      mpq_mul(v, v, m[i][3]);
      if ((i + 3) % 2) mpq_sub(det, det, v);
      else mpq_add(det, det, v);
    }
  }
  const int s = mpq_sgn(det);
  mpq_clears(t, u, v, det, NULL);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) mpq_clear(m[i][j]);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) mpq_clear(minor[i][j]);
  return s;
}

int dtlab_orient3d(const double* a, const double* b, const double* c, const double* d) {
  const double* p[3] = {a, b, c};
  return lifted_sign(p, 3, d);
}

/* insphere is the lifted determinant of the rows a-e, b-e, c-e, d-e (positive when e
 * is inside and orient3d(a,b,c,d) > 0). */
int dtlab_insphere(const double* a, const double* b, const double* c, const double* d, const double* e) {
  const double* p[4] = {a, b, c, d};
  return lifted_sign(p, 4, e);
}

const char* dtlab_backend_name(void) { return "plugin-exact"; }
