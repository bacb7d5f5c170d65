/* port/st7789.c - Sitronix ST7789 presets (240x320 frame memory).
 *
 * The controller drives up to 240 columns x 320 rows. Smaller modules show a
 * window of that memory, so their visible area starts at a RAM offset that
 * depends on how MADCTL mirrors the addresses:
 *
 *   module    glass in RAM (rotation 0)       offset (x, y) per rotation
 *   240x320   cols 0..239,  rows 0..319       0: (0,0)   1: (0,0)   2: (0,0)   3: (0,0)
 *   240x240   cols 0..239,  rows 0..239       0: (0,0)   1: (0,0)   2: (0,80)  3: (80,0)
 *   135x240   cols 52..186, rows 40..279      0: (52,40) 1: (40,53) 2: (53,40) 3: (40,52)
 *
 * Derivation: with MV the logical x addresses rows; MX/MY then mirror the
 * physical column (239 - c) / row (319 - r). A glass starting at column c0
 * with width w seen through a mirror starts at 240 - c0 - w: 240-52-135 = 53
 * for the 135-wide glass, 320-0-240 = 80 for the 240x240 glass rows.
 *
 * MADCTL per rotation: 0, MX|MV, MX|MY, MY|MV (the usual upright orientation
 * of these modules). The IPS glass of these modules is normally-black with
 * inverted data, hence FXL_PANEL_INVERT; colour order is RGB.
 *
 * Vendor registers (porch, gate, VCOM, power) keep their reset defaults,
 * which the datasheet specifies for a 240x320 panel; only DCS commands are
 * sent, by fxl_panel_init.
 */
#include "fixel/port.h"

#define ST7789_MADCTL { 0x00u, FXL_MADCTL_MX | FXL_MADCTL_MV, FXL_MADCTL_MX | FXL_MADCTL_MY, \
                        FXL_MADCTL_MY | FXL_MADCTL_MV }

const fxl_panel_preset_t fxl_st7789_240x320 = {
    "st7789-240x320", 240, 320, ST7789_MADCTL,
    { { 0, 0 }, { 0, 0 }, { 0, 0 }, { 0, 0 } },
    FXL_PANEL_INVERT, FXL_COLMOD_RGB565, NULL, 0
};

const fxl_panel_preset_t fxl_st7789_240x240 = {
    "st7789-240x240", 240, 240, ST7789_MADCTL,
    { { 0, 0 }, { 0, 0 }, { 0, 80 }, { 80, 0 } },
    FXL_PANEL_INVERT, FXL_COLMOD_RGB565, NULL, 0
};

const fxl_panel_preset_t fxl_st7789_135x240 = {
    "st7789-135x240", 135, 240, ST7789_MADCTL,
    { { 52, 40 }, { 40, 53 }, { 53, 40 }, { 40, 52 } },
    FXL_PANEL_INVERT, FXL_COLMOD_RGB565, NULL, 0
};
