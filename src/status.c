/* status.c - names of the fxl_status_t codes (see include/fixel/status.h). */
#include "fixel/status.h"

const char *fxl_status_name(fxl_status_t status)
{
    /* A switch over the value, not a table indexed by it: a value that is
     * not one of the enumerators (a cast from an integer) falls through to
     * the final return, never indexes out of bounds. No default label, so
     * -Wswitch flags a code added to the enum but not named here. */
    switch (status) {
    case FXL_OK:
        return "FXL_OK";
    case FXL_ERR_ARG:
        return "FXL_ERR_ARG";
    case FXL_ERR_RANGE:
        return "FXL_ERR_RANGE";
    case FXL_ERR_UNSUPPORTED:
        return "FXL_ERR_UNSUPPORTED";
    case FXL_ERR_NOMEM:
        return "FXL_ERR_NOMEM";
    case FXL_ERR_BUSY:
        return "FXL_ERR_BUSY";
    case FXL_ERR_IO:
        return "FXL_ERR_IO";
    }
    return "FXL_ERR_UNKNOWN";
}
