/* test_vertex.c - see test_vertex.h. */
#include <math.h>
#include "test_vertex.h"

fxl_vertex_t test_vertex(double x, double y, double inv_w, double u, double v, uint16_t color)
{
    fxl_vertex_t r;
    r.x = (fxl_q16_t)lround(x * 65536.0);
    r.y = (fxl_q16_t)lround(y * 65536.0);
    r.inv_w = (uint32_t)llround(inv_w * 4294967295.0);
    if (r.inv_w == 0)
        r.inv_w = 1;
    r.u = (fxl_q16_t)lround(u * 65536.0);
    r.v = (fxl_q16_t)lround(v * 65536.0);
    r.color = color;
    return r;
}

fxl_vertex_t test_project(double x, double y, double z, double u, double v)
{
    double f = 1.0 / tan(3.14159265358979323846 / 6.0), w = -z;
    double sx = (f * 0.75 * x / w * 0.5 + 0.5) * 320.0, sy = (0.5 - f * y / w * 0.5) * 240.0;
    return test_vertex(sx, sy, 1.0 / w, u, v, 0xFFFF);
}
