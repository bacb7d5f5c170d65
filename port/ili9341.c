/* port/ili9341.c - Ilitek ILI9341 preset (240x320, no RAM offset).
 *
 * Common modules wire the source outputs right to left, so the upright
 * portrait orientation needs MX; the glass is BGR. MADCTL per rotation:
 * MX, MV, MY, MX|MY|MV (+ BGR from the flags). Offsets are all zero.
 *
 * Init steps after SLPOUT (values from the ILI9341 register descriptions;
 * they set the module's supply levels, not anything fixel depends on):
 *   C0 PWCTR1  0x23          GVDD = 4.60 V
 *   C1 PWCTR2  0x10          step-up factor for VGH/VGL
 *   C5 VMCTR1  0x3E 0x28     VCOMH = 4.250 V, VCOML = -1.500 V
 *   C7 VMCTR2  0x86          VCOM offset (nVM = 1, VMF = 6)
 *   B1 FRMCTR1 0x00 0x18     fosc / 1, 24 clocks per line: 79 Hz
 *   B6 DFUNCTR 0x08 0x82 0x27  scan mode, normally-white glass, 320 lines (NL = 0x27)
 *   26 GAMSET  0x01          gamma curve 1
 */
#include "fixel/port.h"

static const fxl_dcs_step_t ili9341_steps[] = {
    { 0xC0u, 1, 0, { 0x23u } },
    { 0xC1u, 1, 0, { 0x10u } },
    { 0xC5u, 2, 0, { 0x3Eu, 0x28u } },
    { 0xC7u, 1, 0, { 0x86u } },
    { 0xB1u, 2, 0, { 0x00u, 0x18u } },
    { 0xB6u, 3, 0, { 0x08u, 0x82u, 0x27u } },
    { 0x26u, 1, 0, { 0x01u } },
};

const fxl_panel_preset_t fxl_ili9341_240x320 = {
    "ili9341-240x320", 240, 320,
    { FXL_MADCTL_MX, FXL_MADCTL_MV, FXL_MADCTL_MY, FXL_MADCTL_MX | FXL_MADCTL_MY | FXL_MADCTL_MV },
    { { 0, 0 }, { 0, 0 }, { 0, 0 }, { 0, 0 } },
    FXL_PANEL_BGR, FXL_COLMOD_RGB565, ili9341_steps,
    (uint8_t)(sizeof(ili9341_steps) / sizeof(ili9341_steps[0]))
};
