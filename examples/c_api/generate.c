/* Runs the grammar examples/stem_leaf.fgsg compiled ahead of time into libstem_leaf.so
 * (see README.md here): one seed, one output file, the counts on stdout.
 *
 *   usage: generate SEED OUT.glb|.obj|.ply */
#include "stem_leaf.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>

int main(int argc, char** argv) {
  if (argc != 3) {
    fprintf(stderr, "usage: %s SEED OUT.glb|.obj|.ply\n", argv[0]);
    return 2;
  }
  char* end = NULL;
  errno = 0;
  const unsigned long long seed = strtoull(argv[1], &end, 10);
  if (argv[1][0] == '\0' || argv[1][0] == '-' || *end != '\0' || errno == ERANGE) {
    fprintf(stderr, "%s: the seed must be a whole number >= 0, got '%s'\n", argv[0], argv[1]);
    return 2;
  }

  fgsg_generator* g = stem_leaf_create();
  if (!g) {
    fprintf(stderr, "%s: out of memory\n", argv[0]);
    return 1;
  }
  if (fgsg_set_seed(g, seed) != 0 || fgsg_generate(g) != 0 || fgsg_write(g, argv[2]) != 0) {
    fprintf(stderr, "%s: %s\n", argv[0], fgsg_last_error(g));
    fgsg_generator_free(g);
    return 1;
  }
  fputs(fgsg_warnings(g), stderr);
  printf("vertices %zu\ntriangles %zu\ninstances %zu\n", fgsg_vertex_count(g),
         fgsg_index_count(g) / 3, fgsg_instance_count(g));
  fgsg_generator_free(g);
  return 0;
}
