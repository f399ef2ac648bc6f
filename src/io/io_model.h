/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The model a reader fills: surface and curve handles plus the list of
 * entities it did not read. Readers add raw geometry (io_geom.h); the model
 * turns it into handles through the public creation functions, so a file
 * and a caller building the same spline get the same validation.
 */
#ifndef PC_IO_MODEL_H
#define PC_IO_MODEL_H

#include <stddef.h>

#include "common/error.h"
#include "io/io_geom.h"
#include "projcurve.h"

/* More skipped entities than this are counted in one summary line. */
#define PC_MODEL_MAX_SKIPPED_LISTED 100000
#define PC_MODEL_SKIPPED_TEXT 160

struct projcurve_model {
    projcurve_surface **surfaces;
    size_t n_surfaces, cap_surfaces;
    projcurve_curve **curves;
    size_t n_curves, cap_curves;
    char **skipped;
    size_t n_skipped, cap_skipped;
    size_t n_skipped_unlisted;
    int unit; /* the file's length unit, PROJCURVE_UNIT_* (0: the file does not say) */
};

/* An empty model (NULL on allocation failure). */
projcurve_model *pc_model_new(void);
void pc_model_free(projcurve_model *model);

/* Creates a surface/curve handle from raw data and appends it. On failure
 * the creation status is returned and the message is prefixed by `origin`
 * (e.g. "IGES entity 128 at DE 5"). Weights that are all equal are dropped
 * (the spline is polynomial then). */
projcurve_status pc_model_add_surface(projcurve_context *ctx, projcurve_model *model,
                                      const pc_io_surface *s, const char *origin);
projcurve_status pc_model_add_curve(projcurve_context *ctx, projcurve_model *model,
                                    const pc_io_curve *c, const char *origin);

/* Appends a description of an entity that was not read. */
projcurve_status pc_model_add_skipped(projcurve_context *ctx, projcurve_model *model,
                                      const char *fmt, ...) PC_PRINTF(3, 4);

/* Adds the line "... and N more skipped entities" once the list is full. */
projcurve_status pc_model_note_unlisted(projcurve_context *ctx, projcurve_model *model);

/* The readers, one per format. Each fills model from data[0..len) (data is
 * NUL-terminated at len) and returns OK or the first error, with a message
 * naming the line or the entity. */
projcurve_status pc_iges_read(projcurve_context *ctx, const char *data, size_t len,
                              projcurve_model *model);
projcurve_status pc_step_read(projcurve_context *ctx, const char *data, size_t len,
                              projcurve_model *model);
/* The length unit a STEP text declares (step_unit.c), PROJCURVE_UNIT_*;
 * PROJCURVE_UNIT_UNKNOWN when none is recognised. */
int pc_step_length_unit(const char *text, size_t len);
projcurve_status pc_gismo_read(projcurve_context *ctx, const char *data, size_t len,
                               projcurve_model *model);
projcurve_status pc_teapot_read(projcurve_context *ctx, const char *data, size_t len,
                                projcurve_model *model);

typedef enum pc_file_format {
    PC_FORMAT_UNKNOWN = 0,
    PC_FORMAT_IGES,
    PC_FORMAT_STEP,
    PC_FORMAT_GISMO,
    PC_FORMAT_TEAPOT
} pc_file_format;

/* Recognises the format from the first bytes of the file. */
pc_file_format pc_detect_format(const char *data, size_t len);

#endif /* PC_IO_MODEL_H */
