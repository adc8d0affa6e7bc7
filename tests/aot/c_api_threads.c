/* The C API from N threads (scripts/tsan.sh runs it with 8 under ThreadSanitizer; first
 * written as the reproducer shared/repro/c_api_threads_same_path.c of the same-path
 * write bug, tests/unit/c_api/test_c_api_threads.cpp). */
/* Runs one compiled grammar with N seeds, first one after another, then all at once in
 * N threads, and checks each threaded result equals the sequential one (mesh arrays,
 * instances, warnings). Then N threads fgsg_write different results to ONE path at
 * once and checks the file equals one of the results byte for byte.
 *   threads LIB.so PROGRAM_SYMBOL NTHREADS ROUNDS [max-shapes] */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <pthread.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "backend/aot/fgsg_api.h"

typedef struct {
  uint64_t seed;
  size_t nv, ni, ninst;
  uint64_t hash;
  int rc;
  char err[512];
  char* warnings;
} Result;

static const struct FgsgProgram* program;
static const char* max_shapes = NULL;
static pthread_barrier_t barrier;

static uint64_t fnv(uint64_t h, const void* p, size_t n) {
  const unsigned char* c = p;
  for (size_t i = 0; i < n; ++i) h = (h ^ c[i]) * 1099511628211ull;
  return h;
}

static void run_one(Result* r) {
  fgsg_generator* g = fgsg_generator_create(program);
  if (!g) { r->rc = -1; return; }
  fgsg_set_seed(g, r->seed);
  if (max_shapes) fgsg_set_option(g, "max-shapes", max_shapes);
  r->rc = fgsg_generate(g);
  snprintf(r->err, sizeof r->err, "%s", fgsg_last_error(g));
  r->nv = fgsg_vertex_count(g);
  r->ni = fgsg_index_count(g);
  r->ninst = fgsg_instance_count(g);
  uint64_t h = 1469598103934665603ull;
  if (r->nv) {
    h = fnv(h, fgsg_positions(g), r->nv * 3 * sizeof(float));
    h = fnv(h, fgsg_normals(g), r->nv * 3 * sizeof(float));
    if (fgsg_colors(g)) h = fnv(h, fgsg_colors(g), r->nv * 3 * sizeof(float));
  }
  if (r->ni) h = fnv(h, fgsg_indices(g), r->ni * sizeof(uint32_t));
  if (r->ninst) {
    h = fnv(h, fgsg_instance_transforms(g), r->ninst * 16 * sizeof(double));
    h = fnv(h, fgsg_instance_assets(g), r->ninst * sizeof(uint32_t));
  }
  r->hash = h;
  r->warnings = strdup(fgsg_warnings(g));
  fgsg_generator_free(g);
}

static void* thread_main(void* arg) {
  pthread_barrier_wait(&barrier);
  run_one((Result*)arg);
  return NULL;
}

typedef struct {
  uint64_t seed;
  const char* path;
  int rc;
  char err[256];
} WriteJob;

static void* write_main(void* arg) {
  WriteJob* j = arg;
  fgsg_generator* g = fgsg_generator_create(program);
  fgsg_set_seed(g, j->seed);
  if (max_shapes) fgsg_set_option(g, "max-shapes", max_shapes);
  fgsg_generate(g);
  pthread_barrier_wait(&barrier);
  j->rc = fgsg_write(g, j->path);
  snprintf(j->err, sizeof j->err, "%s", fgsg_last_error(g));
  fgsg_generator_free(g);
  return NULL;
}

static char* slurp(const char* path, size_t* n) {
  FILE* f = fopen(path, "rb");
  if (!f) return NULL;
  fseek(f, 0, SEEK_END);
  long len = ftell(f);
  fseek(f, 0, SEEK_SET);
  char* buf = malloc(len + 1);
  *n = fread(buf, 1, len, f);
  fclose(f);
  return buf;
}

int main(int argc, char** argv) {
  if (argc < 5) {
    fprintf(stderr, "usage: %s LIB.so SYMBOL NTHREADS ROUNDS [max-shapes]\n", argv[0]);
    return 2;
  }
  void* lib = dlopen(argv[1], RTLD_NOW);
  if (!lib) { fprintf(stderr, "%s\n", dlerror()); return 2; }
  program = dlsym(lib, argv[2]);
  if (!program) { fprintf(stderr, "%s\n", dlerror()); return 2; }
  const int n = atoi(argv[3]), rounds = atoi(argv[4]);
  if (argc > 5) max_shapes = argv[5];
  Result* seq = calloc(n, sizeof(Result));
  for (int i = 0; i < n; ++i) {
    seq[i].seed = 100 + i;
    run_one(&seq[i]);
    printf("seq seed %llu rc %d nv %zu ni %zu inst %zu hash %016llx %s\n", (unsigned long long)seq[i].seed, seq[i].rc,
           seq[i].nv, seq[i].ni, seq[i].ninst, (unsigned long long)seq[i].hash, seq[i].rc ? seq[i].err : "");
  }
  int mismatches = 0;
  for (int round = 0; round < rounds; ++round) {
    Result* par = calloc(n, sizeof(Result));
    pthread_t* th = calloc(n, sizeof(pthread_t));
    pthread_barrier_init(&barrier, NULL, n);
    for (int i = 0; i < n; ++i) {
      par[i].seed = 100 + i;
      pthread_create(&th[i], NULL, thread_main, &par[i]);
    }
    for (int i = 0; i < n; ++i) pthread_join(th[i], NULL);
    pthread_barrier_destroy(&barrier);
    for (int i = 0; i < n; ++i) {
      const int same = par[i].rc == seq[i].rc && par[i].hash == seq[i].hash && par[i].nv == seq[i].nv &&
                       par[i].ni == seq[i].ni && par[i].ninst == seq[i].ninst &&
                       strcmp(par[i].warnings, seq[i].warnings) == 0 && strcmp(par[i].err, seq[i].err) == 0;
      if (!same) {
        ++mismatches;
        printf("MISMATCH round %d seed %llu: rc %d/%d hash %016llx/%016llx inst %zu/%zu err '%s'\n", round,
               (unsigned long long)par[i].seed, par[i].rc, seq[i].rc, (unsigned long long)par[i].hash,
               (unsigned long long)seq[i].hash, par[i].ninst, seq[i].ninst, par[i].err);
      }
    }
    printf("round %d done\n", round);
    free(par);
    free(th);
  }
  /* All threads write to one path at once. */
  const char* path = "same_target.glb";
  char ref[64];
  WriteJob* jobs = calloc(n, sizeof(WriteJob));
  pthread_t* th = calloc(n, sizeof(pthread_t));
  pthread_barrier_init(&barrier, NULL, n);
  for (int i = 0; i < n; ++i) {
    jobs[i].seed = 100 + i;
    jobs[i].path = path;
    pthread_create(&th[i], NULL, write_main, &jobs[i]);
  }
  for (int i = 0; i < n; ++i) pthread_join(th[i], NULL);
  int write_failures = 0;
  for (int i = 0; i < n; ++i)
    if (jobs[i].rc) { ++write_failures; printf("concurrent write %d failed: %s\n", i, jobs[i].err); }
  size_t got_n = 0;
  char* got = slurp(path, &got_n);
  int matched = -1;
  for (int i = 0; i < n && got; ++i) {
    fgsg_generator* g = fgsg_generator_create(program);
    fgsg_set_seed(g, 100 + i);
    if (max_shapes) fgsg_set_option(g, "max-shapes", max_shapes);
    fgsg_generate(g);
    snprintf(ref, sizeof ref, "ref_%d.glb", i);
    fgsg_write(g, ref);
    fgsg_generator_free(g);
    size_t rn = 0;
    char* r = slurp(ref, &rn);
    if (r && rn == got_n && memcmp(r, got, rn) == 0) matched = i;
    free(r);
    unlink(ref);
  }
  printf("concurrent writes to one path: %d failed; final file %zu bytes %s\n", write_failures, got_n,
         matched >= 0 ? "equals one writer's result" : "MATCHES NO WRITER (corrupt)");
  printf("mismatches %d\n", mismatches);
  return mismatches || matched < 0;
}
