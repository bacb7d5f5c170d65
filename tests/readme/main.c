/* main.c - drives the README's API example (tests/readme/readme_example.cmake
 * extracts it to example.c; included here so its caller-owned buffers can
 * be inspected): a quad across the target, receding towards the top, then a
 * check that it drew textured pixels inside the quad and left the clear
 * colour outside. draw_quad spins on an error: CTest's timeout catches it. */
#include <stdio.h>
#include "example.c"

static fxl_vertex_t vert(int x, int y, uint32_t inv_w, int u, int v)
{
    fxl_vertex_t r;
    r.x = (fxl_q16_t)(x * 65536);
    r.y = (fxl_q16_t)(y * 65536);
    r.inv_w = inv_w;
    r.u = (fxl_q16_t)(u * 65536);
    r.v = (fxl_q16_t)(v * 65536);
    r.color = 0xFFFFu;
    return r;
}

int main(void)
{
    const fxl_vertex_t quad[4] = {vert(100, 40, 0x40000000u, 0, 0), vert(220, 40, 0x40000000u, 4, 0),
                                  vert(280, 200, 0xFFFFFFFFu, 4, 4), vert(40, 200, 0xFFFFFFFFu, 0, 4)};
    const uint16_t clear = FXL_RGB565(16, 16, 32);
    uint32_t inside = 0, drawn = 0, distinct = 0;
    uint16_t seen[8];
    int x, y, k;
    draw_quad(quad);
    for (y = 0; y < 240; y++)
        for (x = 0; x < 320; x++) {
            const uint16_t p = pixels[y * 320 + x];
            /* well inside the quad: rows 50..190, between its edges */
            const int lx = 100 - (y - 40) * 60 / 160 + 4, rx = 220 + (y - 40) * 60 / 160 - 4;
            if (y >= 50 && y < 190 && x >= lx && x < rx) {
                inside++;
                drawn += p != clear;
                for (k = 0; k < (int)distinct && seen[k] != p; k++)
                    ;
                if (k == (int)distinct && distinct < 8)
                    seen[distinct++] = p;
            } else if ((y < 38 || y > 202 || x < 38 || x > 282) && p != clear) {
                printf("pixel (%d, %d) outside the quad was drawn\n", x, y);
                return 1;
            }
        }
    printf("README example: %u of %u pixels inside the quad drawn, %u+ distinct colours\n", (unsigned)drawn,
           (unsigned)inside, (unsigned)distinct);
    return drawn == inside && distinct >= 4 ? 0 : 1;
}
