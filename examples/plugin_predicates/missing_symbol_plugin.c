/* Not a complete plug-in (tests): dtlab_insphere is missing, so loading it must fail
 * with a message that names the symbol. */
int dtlab_orient3d(const double* a, const double* b, const double* c, const double* d) {
  (void)a, (void)b, (void)c, (void)d;
  return 0;
}
