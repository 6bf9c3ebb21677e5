/* SPDX-License-Identifier: BSD-2-Clause */
/**
 * @file
 * @brief The host's reference of the conformance digest's records
 *        (host variant only):
 *
 *        golden-trace expected   tests/golden/golden_expected.c
 *        golden-trace <part>     every record of a part with its input
 *
 *        A record line reads "golden trace of <part>: <index> <function>
 *        <value> <name>=<input>, ...", the test runner's line plus the
 *        inputs, which a port does not print.
 */
#include <inttypes.h>
#include <stdio.h>
#include <string.h>

#include "golden.h"
#include "golden_parts.h"

static void print_inputs(const golden_t *g)
{
  unsigned k;

  for (k = 0u; k < g->input_count; k++) {
    const golden_input_t *in = &g->inputs[k];

    printf("%s%s=", k == 0u ? " " : ", ", in->name);
    if (in->text != NULL) {
      /* bytes of a text as C escapes: an input may hold any byte */
      const unsigned char *c = (const unsigned char *)in->text;

      putchar('"');
      for (; *c != '\0'; c++) {
        if ((*c < 0x20u) || (*c >= 0x7Fu) || (*c == '"') || (*c == '\\')) {
          printf("\\x%02x", *c);
        } else {
          putchar(*c);
        }
      }
      putchar('"');
    } else {
      printf("%" PRId64, in->value);
    }
  }
}

static void print_record(void *context, const golden_t *g, uint64_t value,
                         unsigned bytes)
{
  const golden_part_t *part = context;

  printf("golden trace of %s: %" PRIu32 " %s 0x%0*" PRIx64, part->name,
         g->records, g->function != NULL ? g->function : "?", (int)(2u * bytes),
         value);
  print_inputs(g);
  putchar('\n');
}

static void print_block(void *context, uint32_t block, uint32_t digest)
{
  (void)context;
  printf("%s0x%08" PRIx32 "u,", (block % 5u) == 0u ? "\n    " : " ", digest);
}

/* tests/golden/golden_expected.c: the records and block digests of every
 * part as this host computes them. */
static void print_expected(void)
{
  unsigned k;

  printf("/* SPDX-License-Identifier: BSD-2-Clause */\n"
         "/**\n * @file\n"
         " * @brief Records and block digests of each part as the host\n"
         " *        computes them. Written by\n"
         " *        build/host/fw/golden-trace/golden-trace expected.\n"
         " */\n#include \"golden_parts.h\"\n");
  for (k = 0u; k < GOLDEN_PARTS; k++) {
    golden_blocks_t blocks;
    golden_t g;

    printf("\nstatic const uint32_t blocks_%u[] = {", k);
    golden_start(&g, GOLDEN_SEED);
    golden_blocks_start(&blocks, &g, print_block, NULL);
    golden_parts[k].run(&g);
    golden_blocks_end(&blocks, &g);
    printf("\n};\n");
  }
  printf("\nconst golden_expected_t golden_expected[GOLDEN_PARTS] = {\n");
  for (k = 0u; k < GOLDEN_PARTS; k++) {
    golden_t g;

    golden_start(&g, GOLDEN_SEED);
    golden_parts[k].run(&g);
    printf("    {%" PRIu32 "u, sizeof blocks_%u / sizeof blocks_%u[0], "
           "blocks_%u},\n",
           g.records, k, k, k);
  }
  printf("};\n");
}

int main(int argc, char **argv)
{
  unsigned k;

  if ((argc == 2) && (strcmp(argv[1], "expected") == 0)) {
    print_expected();
    return 0;
  }
  for (k = 0u; (argc == 2) && (k < GOLDEN_PARTS); k++) {
    if (strcmp(argv[1], golden_parts[k].name) == 0) {
      golden_part_t part = golden_parts[k];
      golden_t g;

      golden_start(&g, GOLDEN_SEED);
      g.record = print_record;
      g.context = &part;
      golden_parts[k].run(&g);
      return 0;
    }
  }
  fprintf(stderr, "usage: golden-trace expected | golden-trace <part>\n"
                  "parts:");
  for (k = 0u; k < GOLDEN_PARTS; k++) {
    fprintf(stderr, " \"%s\"", golden_parts[k].name);
  }
  fprintf(stderr, "\n");
  return 2;
}
