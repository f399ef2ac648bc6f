/* SPDX-License-Identifier: BSD-3-Clause */
#include "step_text.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"

int step_add(step_text *t, const char *fmt, ...)
{
    const int id = t->next++;
    t->len += (size_t)snprintf(t->buf + t->len, sizeof t->buf - t->len, "#%d=", id);
    va_list a;
    va_start(a, fmt);
    t->len += (size_t)vsnprintf(t->buf + t->len, sizeof t->buf - t->len, fmt, a);
    va_end(a);
    t->len += (size_t)snprintf(t->buf + t->len, sizeof t->buf - t->len, ";\n");
    return id;
}

projcurve_model *step_read(projcurve_context *ctx, const step_text *t)
{
    static const char head[] = "ISO-10303-21;\nHEADER;\nFILE_NAME('x','',(''),(''),'','','');\n"
                               "ENDSEC;\nDATA;\n";
    static const char tail[] = "ENDSEC;\nEND-ISO-10303-21;\n";
    const size_t len = sizeof head - 1 + t->len + sizeof tail - 1;
    char *doc = malloc(len + 1);
    if (doc == NULL) {
        pc_test_fail_at(__FILE__, __LINE__, "out of memory");
        return NULL;
    }
    snprintf(doc, len + 1, "%s%s%s", head, t->buf, tail);
    projcurve_model *m = NULL;
    if (projcurve_model_read_memory(ctx, doc, len, &m) != PROJCURVE_OK)
        pc_test_fail_at(__FILE__, __LINE__, "read failed: %s", projcurve_context_message(ctx));
    free(doc);
    return m;
}
