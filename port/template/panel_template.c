/* port/template/panel_template.c - start here for a MIPI DCS panel fixel
 * does not know yet. Copy this file next to your firmware (or into port/
 * as <controller>.c), rename the preset, fill in the data, and pass it to
 * fxl_panel_init(). No library file needs editing to drive the panel: a
 * preset is plain data (the host emulator check needs its model added:
 * port/template/README.md).
 *
 * Fill in, from the controller datasheet and the module's schematic:
 *  1. width/height: the visible pixels in the module's own (rotation 0)
 *     orientation.
 *  2. madctl[r]: the MY/MX/MV bits that show the image upright for
 *     rotation r = 0, 90, 180, 270 degrees. Leave BGR out; set
 *     FXL_PANEL_BGR in flags when the glass is BGR.
 *  3. offset[r]: where the visible area starts in controller RAM as seen
 *     through madctl[r]. A glass at RAM column c0 of width w (controller
 *     RAM width W) starts at c0 without MX and at W - c0 - w with MX; rows
 *     likewise with MY and the RAM height; with MV, x and y exchange roles.
 *  4. flags: FXL_PANEL_INVERT for IPS glass that needs INVON.
 *  5. init steps: only the controller-specific registers (power, VCOM,
 *     gamma, frame rate) that differ from their reset defaults. Reset,
 *     SLPOUT, COLMOD, MADCTL, INVON/INVOFF, NORON and DISPON are sent by
 *     fxl_panel_init() with the datasheet delays.
 *
 * Check it on the host before touching hardware: add the module's glass
 * geometry to host_sim/lib/panel_emu.c and run the emulator tests: every
 * rotation must show the frame upright with no write outside the glass.
 */
#include "fixel/port.h"

static const fxl_dcs_step_t my_panel_steps[] = {
    /* { command, parameter count, delay in ms after it, { parameters } } */
    { 0x00u /* NOP: replace with e.g. a power-control register */, 0, 0, { 0 } },
};

const fxl_panel_preset_t my_panel_preset = {
    "my-panel", 240, 320,
    { 0x00u, FXL_MADCTL_MX | FXL_MADCTL_MV, FXL_MADCTL_MX | FXL_MADCTL_MY,
      FXL_MADCTL_MY | FXL_MADCTL_MV },
    { { 0, 0 }, { 0, 0 }, { 0, 0 }, { 0, 0 } },
    0 /* FXL_PANEL_BGR | FXL_PANEL_INVERT as the glass needs */,
    FXL_COLMOD_RGB565,
    my_panel_steps,
    (uint8_t)(sizeof(my_panel_steps) / sizeof(my_panel_steps[0]))
};
