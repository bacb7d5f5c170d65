/* host_sim/tools/texconv.c - fixel-texconv: PNG -> mip-mapped fixel texture as C
 * source and/or a raw blob. All the work is in host_sim/lib/texconv_lib.c
 * (shared with tests/test_texconv.c); run with --help for the options. */
#include "texconv_lib.h"

int main(int argc, char **argv)
{
    return texconv_main(argc, argv);
}
