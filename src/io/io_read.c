/* SPDX-License-Identifier: BSD-3-Clause */
/* A model from a file's text: the format recognised, its reader run. */
#include "common/error.h"
#include "io/io_model.h"

projcurve_status pc_model_read_text(projcurve_context *ctx, const char *data, size_t len,
                                    projcurve_model **out)
{
    projcurve_model *model = pc_model_new();
    if (model == NULL)
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory creating a model");
    projcurve_status st;
    switch (pc_detect_format(data, len)) {
    case PC_FORMAT_IGES: st = pc_iges_read(ctx, data, len, model); break;
    case PC_FORMAT_STEP: st = pc_step_read(ctx, data, len, model); break;
    case PC_FORMAT_GISMO: st = pc_gismo_read(ctx, data, len, model); break;
    case PC_FORMAT_TEAPOT: st = pc_teapot_read(ctx, data, len, model); break;
    default:
        st = pc_fail(ctx, PROJCURVE_ERR_PARSE,
                     "unrecognised file format (not IGES, STEP, G+Smo XML or Newell teapot text)");
    }
    if (st == PROJCURVE_OK && model->n_skipped_unlisted > 0)
        st = pc_model_note_unlisted(ctx, model);
    if (st != PROJCURVE_OK) {
        pc_model_free(model);
        return st;
    }
    *out = model;
    return PROJCURVE_OK;
}
