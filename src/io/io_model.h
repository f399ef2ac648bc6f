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
#define PC_MODEL_KIND_TEXT 24

struct projcurve_model {
    projcurve_surface **surfaces;
    /* The kind of each surface as read from the file ("bspline", "plane",
     * "cylinder", ...: static strings), parallel to surfaces. */
    const char **surface_kinds;
    size_t n_surfaces, cap_surfaces, cap_kinds;
    /* The file's length unit in metres and its distance precision in model
     * units, each when the file states it (has_* = 1). */
    double metres_per_unit, precision;
    int has_length_unit, has_precision;
    projcurve_curve **curves;
    size_t n_curves, cap_curves;
    char **skipped;
    size_t n_skipped, cap_skipped;
    size_t n_skipped_unlisted;
    /* Topology (io_topology.c): faces and shapes the model owns, and the
     * faces that could not be built, each with its file kind and reason. */
    projcurve_face **faces;
    size_t n_faces, cap_faces;
    projcurve_shape **shapes;
    size_t n_shapes, cap_shapes;
    char **unbuilt;
    char (*unbuilt_kind)[PC_MODEL_KIND_TEXT];
    size_t n_unbuilt, cap_unbuilt;
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
/* The same with the surface's kind (a static string). */
projcurve_status pc_model_add_surface_kind(projcurve_context *ctx, projcurve_model *model,
                                           const pc_io_surface *s, const char *origin,
                                           const char *kind);
projcurve_status pc_model_add_curve(projcurve_context *ctx, projcurve_model *model,
                                    const pc_io_curve *c, const char *origin);

/* Appends a description of an entity that was not read. */
projcurve_status pc_model_add_skipped(projcurve_context *ctx, projcurve_model *model,
                                      const char *fmt, ...) PC_PRINTF(3, 4);

/* Adds the line "... and N more skipped entities" once the list is full. */
projcurve_status pc_model_note_unlisted(projcurve_context *ctx, projcurve_model *model);

/* Takes a face / shape into the model (on failure, NO_MEMORY, it is
 * released). */
projcurve_status pc_model_add_face(projcurve_context *ctx, projcurve_model *model,
                                   projcurve_face *face);
projcurve_status pc_model_add_shape(projcurve_context *ctx, projcurve_model *model,
                                    projcurve_shape *shape);
/* Lists a face that could not be built: its file kind ("plane") and why. */
projcurve_status pc_model_add_unbuilt(projcurve_context *ctx, projcurve_model *model,
                                      const char *kind, const char *fmt, ...) PC_PRINTF(4, 5);

/* The readers, one per format. Each fills model from data[0..len) (data is
 * NUL-terminated at len) and returns OK or the first error, with a message
 * naming the line or the entity. */
projcurve_status pc_iges_read(projcurve_context *ctx, const char *data, size_t len,
                              projcurve_model *model);
projcurve_status pc_step_read(projcurve_context *ctx, const char *data, size_t len,
                              projcurve_model *model);
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

/* A new model read from data[0..len) (NUL-terminated at len) by the reader
 * of its format (io_read.c). Statuses: OK, PARSE (unrecognised format or
 * the reader's error), the readers' others, NO_MEMORY; *out is set on OK
 * only. */
projcurve_status pc_model_read_text(projcurve_context *ctx, const char *data, size_t len,
                                    projcurve_model **out);

#endif /* PC_IO_MODEL_H */
