/* A test driver for compiled grammar libraries: loads LIBRARY (libNAME.so, built by
 * fgsg compile) with dlopen, finds its program `fgsg_program_NAME`, maps fgsg run's
 * flags onto the C API (backend/aot/fgsg_api.h), generates and writes the mesh. Used to
 * check that a compiled library gives fgsg run's bytes.
 *
 *   usage: run_library LIBRARY [--name NAME] -o OUT [--seed N] [--set name=value]...
 *            [--surface FILE] [--surface-size S] [--start x,y,z] [--repair-surface]
 *            [--collide-all] [--max-shapes N] [--max-depth N] [--step N] [--max-seconds S]
 *            [--asset-dir DIR] [--lots FILE] [--quiet]
 *
 * Exit codes: 0 success, 1 failure (the message on stderr), 2 bad usage or a value
 * fgsg_set_option refuses. */
#include "backend/aot/fgsg_api.h"

#include <dlfcn.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char* prog = "run_library";

static int usage(const char* message, const char* arg) {
  fprintf(stderr, "%s: %s%s%s\n", prog, message, arg ? " " : "", arg ? arg : "");
  return 2;
}

/* NAME of .../libNAME.so, as fgsg compile derives it ('-' and '.' become '_'). */
static int symbolName(const char* path, char* out, size_t size) {
  const char* file = strrchr(path, '/');
  file = file ? file + 1 : path;
  size_t len = strlen(file);
  if (len < 3 || strcmp(file + len - 3, ".so") != 0) return 0;
  len -= 3;
  if (strncmp(file, "lib", 3) == 0) file += 3, len -= 3;
  if (len == 0 || len + 1 > size) return 0;
  for (size_t i = 0; i < len; ++i) out[i] = (file[i] == '-' || file[i] == '.') ? '_' : file[i];
  out[len] = '\0';
  return 1;
}

int main(int argc, char** argv) {
  if (argc < 2) return usage("usage: run_library LIBRARY -o OUT [fgsg run options]", NULL);
  const char* library = argv[1];
  const char* name = NULL;
  const char* output = NULL;
  int quiet = 0;

  /* First the library and its generator, then the options in order. */
  char nameBuf[512];
  for (int i = 2; i < argc; ++i) {
    if (strcmp(argv[i], "--name") == 0 && i + 1 < argc) name = argv[i + 1];
    if (strncmp(argv[i], "--name=", 7) == 0) name = argv[i] + 7;
  }
  if (!name) {
    if (!symbolName(library, nameBuf, sizeof nameBuf))
      return usage("cannot tell NAME from the library's file name (libNAME.so); give --name NAME:", library);
    name = nameBuf;
  }
  void* handle = dlopen(library, RTLD_NOW | RTLD_LOCAL);
  if (!handle) {
    fprintf(stderr, "%s: %s\n", prog, dlerror());
    return 1;
  }
  char symbol[600];
  snprintf(symbol, sizeof symbol, "fgsg_program_%s", name);
  const struct FgsgProgram* program = (const struct FgsgProgram*)dlsym(handle, symbol);
  if (!program) {
    fprintf(stderr, "%s: %s has no symbol %s\n", prog, library, symbol);
    return 1;
  }
  fgsg_generator* g = fgsg_generator_create(program);
  if (!g) {
    fprintf(stderr, "%s: out of memory\n", prog);
    return 1;
  }
  int rc = 0;
  /* A failed call ends the run: exit 1, or 2 for a bad option value (as fgsg run). */
#define FAIL_WITH(code, call)                               \
  if ((call) != 0) {                                        \
    fprintf(stderr, "%s: %s\n", prog, fgsg_last_error(g)); \
    rc = (code);                                            \
    goto done;                                              \
  }
#define FAIL_IF(call) FAIL_WITH(1, call)

  if (fgsg_last_error(g)[0] != '\0') FAIL_IF(1);
  for (int i = 2; i < argc; ++i) {
    char flag[64];
    const char* arg = argv[i];
    const char* value = NULL;
    const char* eq = strchr(arg, '=');
    if (strncmp(arg, "--", 2) == 0 && eq && (size_t)(eq - arg) < sizeof flag) {
      memcpy(flag, arg, (size_t)(eq - arg));
      flag[eq - arg] = '\0';
      value = eq + 1;
    } else {
      snprintf(flag, sizeof flag, "%s", arg);
    }
    /* Switches take no value. */
    if (strcmp(flag, "--quiet") == 0 || strcmp(flag, "-q") == 0) {
      quiet = 1;
      continue;
    }
    if (strcmp(flag, "--collide-all") == 0 || strcmp(flag, "--repair-surface") == 0) {
      FAIL_WITH(2, fgsg_set_option(g, flag + 2, NULL));
      continue;
    }
    if (!value) {
      if (i + 1 >= argc) {
        rc = usage("needs a value:", flag);
        goto done;
      }
      value = argv[++i];
    }
    if (strcmp(flag, "--name") == 0) continue;
    if (strcmp(flag, "-o") == 0 || strcmp(flag, "--output") == 0) {
      output = value;
    } else if (strcmp(flag, "--seed") == 0) {
      char* end = NULL;
      errno = 0;
      const unsigned long long seed = strtoull(value, &end, 10);
      if (!*value || *value == '-' || *end || errno == ERANGE) {
        rc = usage("--seed expects a whole number >= 0, got", value);
        goto done;
      }
      FAIL_IF(fgsg_set_seed(g, seed));
    } else if (strcmp(flag, "--set") == 0) {
      const char* at = strchr(value, '=');
      if (!at || at == value) {
        rc = usage("--set expects name=value, got", value);
        goto done;
      }
      char key[256];
      if ((size_t)(at - value) >= sizeof key) {
        rc = usage("--set: attribute name too long:", value);
        goto done;
      }
      memcpy(key, value, (size_t)(at - value));
      key[at - value] = '\0';
      FAIL_IF(fgsg_set_attribute(g, key, at + 1));
    } else if (strcmp(flag, "--surface") == 0) {
      if (!*value) {
        rc = usage("--surface needs a mesh file name", NULL);
        goto done;
      }
      FAIL_IF(fgsg_set_surface(g, value));
    } else if (strcmp(flag, "--surface-size") == 0 || strcmp(flag, "--start") == 0 ||
               strcmp(flag, "--max-shapes") == 0 || strcmp(flag, "--max-depth") == 0 ||
               strcmp(flag, "--step") == 0 ||
               strcmp(flag, "--max-seconds") == 0 || strcmp(flag, "--asset-dir") == 0 ||
               strcmp(flag, "--seed-points") == 0 || strcmp(flag, "--seed-density") == 0 ||
               strcmp(flag, "--seed-count") == 0 || strcmp(flag, "--march-candidates") == 0 ||
               strcmp(flag, "--atlas-resolution") == 0 || strcmp(flag, "--march-units") == 0 ||
               strcmp(flag, "--lots") == 0) {
      FAIL_WITH(2, fgsg_set_option(g, flag + 2, value));
    } else {
      rc = usage("unknown option", flag);
      goto done;
    }
  }
  if (!output) {
    rc = usage("no output file given (-o OUT)", NULL);
    goto done;
  }
  FAIL_IF(fgsg_generate(g));
  if (!quiet) fputs(fgsg_warnings(g), stderr);
  FAIL_IF(fgsg_write(g, output));
  if (!quiet)
    fprintf(stderr, "wrote %s (%zu instances, %zu triangles)\n", output, fgsg_instance_count(g),
            fgsg_index_count(g) / 3);

done:
  fgsg_generator_free(g);
  /* The library stays loaded: nothing refers to its code any more, but closing it is
   * not needed before exit. */
  return rc;
}
