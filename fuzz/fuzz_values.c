/* libFuzzer target for the value-file tokenizer (src/util/values.c) that the rho, boundary-tangent and points files
   share: every token is classified as a real and as an integer and rendered for a message. Crashes, sanitizer reports and hangs are
   findings. */
#include "cs_util.h"
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
  CSTokens    t;
  char       *buf = malloc(size + 1), text[40];
  const char *tok;
  size_t      len;
  PetscInt    line, last = 0;
  if (!buf) return 0;
  memcpy(buf, data, size);
  buf[size] = 0;
  memset(&t, 0, sizeof(t));
  CSTokensInit(&t, buf, size);
  while (CSTokensNext(&t, &tok, &len, &line)) {
    double    v;
    long long i;
    if (tok < buf || tok + len > buf + size || !len || line < last) abort(); /* the tokenizer's contract */
    last = line;
    (void)CSTokenReal(tok, len, &v);
    (void)CSTokenInt(tok, len, &i);
    (void)CSTokenText(tok, len, text);
    if (strlen(text) > 32) abort();
  }
  free(buf);
  return 0;
}
