/* fixel/status.h - the status codes every public fixel call that can fail returns.
 *
 * FXL_OK is 0; every error is negative, so `if (st < 0)` catches all of them.
 * Culled triangles (zero area, off target, back-facing) are not errors: they
 * return FXL_OK and are counted in fxl_stats_t.
 */
#ifndef FIXEL_STATUS_H
#define FIXEL_STATUS_H

#ifdef __cplusplus
extern "C" {
#endif

typedef enum fxl_status {
    FXL_OK = 0,
    FXL_ERR_ARG = -1,         /* NULL pointer, zero size, unknown enum value */
    FXL_ERR_RANGE = -2,       /* a number outside its documented range */
    FXL_ERR_UNSUPPORTED = -3, /* valid request this build or texture cannot serve */
    FXL_ERR_NOMEM = -4,       /* caller-provided memory is too small */
    FXL_ERR_BUSY = -5,        /* port: for HAL callbacks to report a busy bus (the driver
                               * returns it as FXL_ERR_IO; fixel itself waits instead) */
    FXL_ERR_IO = -6           /* port: a HAL callback reported failure */
} fxl_status_t;

/* Short English name of a status ("FXL_ERR_RANGE"); never NULL. */
const char *fxl_status_name(fxl_status_t status);

#ifdef __cplusplus
}
#endif
#endif
