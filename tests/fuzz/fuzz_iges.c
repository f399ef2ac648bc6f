/* SPDX-License-Identifier: BSD-3-Clause */
/* libFuzzer target: the IGES 5.3 reader on arbitrary bytes. It must return
 * OK or an error with a message, never crash, hang or leak. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "io/io_model.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    /* The readers expect the NUL that projcurve_model_read_memory adds. */
    char *text = malloc(size + 1);
    projcurve_model *model = pc_model_new();
    if (text != NULL && model != NULL) {
        memcpy(text, data, size);
        text[size] = '\0';
        (void)pc_iges_read(NULL, text, size, model);
    }
    pc_model_free(model);
    free(text);
    return 0;
}
