/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Open CASCADE's readers on a file, for the brep bench: STEPControl_Reader
 * or IGESControl_Reader (by the file's extension), TransferRoots, and the
 * faces and wires of the shape (TopExp_Explorer). Built only where Open
 * CASCADE's data exchange toolkits are installed (PCB_HAVE_OCCT_READ).
 */
#ifndef PCB_OCCT_READ_H
#define PCB_OCCT_READ_H

#ifdef __cplusplus
extern "C" {
#endif

/* Reads path once: seconds of CPU time, faces and wires. Returns 0, or -1
 * when the reader fails. */
int pcb_occt_read(const char *path, double *seconds, int *faces, int *wires);

#ifdef __cplusplus
}
#include <TopoDS_Shape.hxx>
/* The same, keeping the shape (the shape bench projects onto it). */
int pcb_occt_read_shape(const char *path, double *seconds, TopoDS_Shape *shape);
#endif

#endif /* PCB_OCCT_READ_H */
