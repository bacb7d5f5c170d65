/* outfile.h - output files that never leave a half-written result (host only).
 *
 * A regular file is written to a temp file beside it (mkstemp, so a name
 * nobody else controls) and renamed into place once complete: a failed
 * write leaves the old file, or none. A device or FIFO ("-o /dev/null") is
 * written in place: renamed over, the node itself would be replaced (as
 * root, /dev/null became a regular file). A directory is refused (EISDIR).
 *
 *   outfile_open -> write o.f -> outfile_close(o, 0) -> outfile_commit
 *   any failure  -> outfile_abandon (also safe after a commit)
 */
#ifndef FIXEL_HOST_OUTFILE_H
#define FIXEL_HOST_OUTFILE_H

#include <stdio.h>

typedef struct outfile {
    const char *path;
    char *tmp;   /* the temp file while one is open; NULL when written in place */
    FILE *f;
} outfile_t;

/* 0, or -1 with errno set. */
int outfile_open(outfile_t *o, const char *path);
/* Close o->f; on a write error or when `discard`, remove the temp file.
 * 0, or -1. */
int outfile_close(outfile_t *o, int discard);
/* Rename the closed temp file into place (nothing to do in place). 0, or
 * -1 with errno set and the temp file removed. */
int outfile_commit(outfile_t *o);
/* Close and remove whatever is left. */
void outfile_abandon(outfile_t *o);

#endif /* FIXEL_HOST_OUTFILE_H */
