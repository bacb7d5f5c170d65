/* outfile.c - see outfile.h. */
#define _POSIX_C_SOURCE 200809L
#include "outfile.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

int outfile_open(outfile_t *o, const char *path)
{
    size_t n = strlen(path) + 16;
    struct stat st;
    int fd;
    o->path = path;
    o->f = NULL;
    o->tmp = NULL;
    if (stat(path, &st) == 0 && !S_ISREG(st.st_mode)) {
        if (S_ISDIR(st.st_mode)) {
            errno = EISDIR;
            return -1;
        }
        o->f = fopen(path, "wb");
        return o->f != NULL ? 0 : -1;
    }
    o->tmp = (char *)malloc(n);
    if (o->tmp == NULL)
        return -1;
    /* same directory as the target, so rename() stays on one file system */
    snprintf(o->tmp, n, "%s.tmp.XXXXXX", path);
    fd = mkstemp(o->tmp);
    if (fd < 0) {
        free(o->tmp);
        o->tmp = NULL;
        return -1;
    }
    {
        /* mkstemp creates 0600; give the result the usual 0666 & ~umask */
        mode_t mask = umask(0);
        umask(mask);
        (void)fchmod(fd, 0666 & ~mask);
    }
    o->f = fdopen(fd, "wb");
    if (o->f == NULL) {
        close(fd);
        unlink(o->tmp);
        free(o->tmp);
        o->tmp = NULL;
        return -1;
    }
    return 0;
}

int outfile_close(outfile_t *o, int discard)
{
    int bad = discard;
    if (o->f == NULL)
        return -1;
    if (fclose(o->f) != 0)
        bad = 1;
    o->f = NULL;
    if (bad && o->tmp != NULL)
        unlink(o->tmp);
    return bad ? -1 : 0;
}

int outfile_commit(outfile_t *o)
{
    int r;
    if (o->tmp == NULL)
        return 0;
    r = rename(o->tmp, o->path);
    if (r != 0)
        unlink(o->tmp);
    free(o->tmp);
    o->tmp = NULL;
    return r;
}

void outfile_abandon(outfile_t *o)
{
    if (o->f != NULL)
        fclose(o->f);
    o->f = NULL;
    if (o->tmp != NULL) {
        unlink(o->tmp);
        free(o->tmp);
        o->tmp = NULL;
    }
}
