/* test_fuzz_regress.c - every input the fuzzers ever flagged, replayed.
 *
 * Inputs are the bytes of a fixel-fuzz / fuzz_raster case (decoded and
 * checked by tests/fuzz/fuzz_case.h: status codes, canaries and guard
 * pages, clip, determinism, exact coverage, stats). Each entry also fixes the
 * exact status and the number of pixels written, measured when it was added.
 * The checks of memory, status, clip and coverage (10^6 cases per CI run,
 * 2 x 10^7 under ASan+UBSan, 10^5 libFuzzer runs) have found nothing in the
 * core, so the table holds the seed inputs below (edge byte patterns and
 * random cases covering the error paths) plus hand-made extreme cases. Check
 * 7 (texel values against each mode's error bound) found core defects (the
 * entries that say "Fixed") and places where its reference was narrower
 * than the documented contract (the three entries before the last); check 8
 * (depth values against the exact plane) found the last one. Add
 * every future finding here with the bytes printed by fixel-fuzz ("FINDING
 * ... bytes <hex>"). A change to the decoder must keep every input here decoding as before (the level-row
 * vertex layout, for one, skips the layout bytes these inputs use).
 *
 * Front-end inputs (fuzz/fuzz_pipe.h: bits 3..5 of the last byte 0) have
 * their own table, pipe_replays, plus hand-made cases at the limits of
 * pipeline.h. The front-end fuzz found three places where the core
 * answered otherwise than pipeline.h says; all three are fixed in the core
 * and pinned by tests in test_pipeline.c:
 *  - fxl_mat4_rotate_axis({65792, 0, 0}, a): |axis| = 1 + 2^-8 exactly,
 *    documented valid, was FXL_ERR_RANGE (the test was | |a|^2 - 1 | <=
 *    2^-7, off by 2^16 in |a|^2 q32 at both ends);
 *  - fxl_mat4_perspective(m, fovy 1, aspect 1, near 1, far 0): documented
 *    valid (cot(fovy / 2) = 20861 fits q16), was FXL_ERR_RANGE because
 *    fovy / 2 was taken in whole units (0); odd fovy lost half a unit;
 *  - fxl_mat4_transform_point(identity with m[3][0] = 1.0, m[3][3] =
 *    INT32_MAX, p = (1, 0, 0)) was FXL_ERR_RANGE although the fourth row is
 *    documented as ignored (it was computed and its overflow reported).
 *    Same for fxl_mat4_transform_vector.
 */
#include <stdio.h>
#include <string.h>

#include "unity.h"
#include "fuzz/fuzz_pipe.h"
#include "test_features.h"

void setUp(void) {}
void tearDown(void) {}

static fz_state st;
static fz_pstate pst;

typedef struct replay {
    const char *hex;
    fxl_status_t status;
    unsigned written;
} replay_t;

static const replay_t replays[] = {
    {"",
     FXL_OK, 0},
    {"ffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffff"
         "ffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffff"
         "ffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffff"
         "ffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffff"
         "ffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffff"
         "ffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffffff",
     FXL_ERR_ARG, 0},
    {"0000000000000000000000000000000000000000000000000000000000000000"
         "0000000000000000000000000000000000000000000000000000000000000000"
         "0000000000000000000000000000000000000000000000000000000000000000"
         "0000000000000000000000000000000000000000000000000000000000000000"
         "0000000000000000000000000000000000000000000000000000000000000000"
         "0000000000000000000000000000000000000000000000000000000000000000",
     FXL_OK, 0},
    {"8080808080808080808080808080808080808080808080808080808080808080"
         "8080808080808080808080808080808080808080808080808080808080808080"
         "8080808080808080808080808080808080808080808080808080808080808080"
         "8080808080808080808080808080808080808080808080808080808080808080"
         "8080808080808080808080808080808080808080808080808080808080808080"
         "8080808080808080808080808080808080808080808080808080808080808080",
     FXL_OK, 0},
    {"7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f"
         "7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f"
         "7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f"
         "7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f"
         "7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f"
         "7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f7f",
     FXL_OK, 0},
    {"0101010101010101010101010101010101010101010101010101010101010101"
         "0101010101010101010101010101010101010101010101010101010101010101"
         "0101010101010101010101010101010101010101010101010101010101010101"
         "0101010101010101010101010101010101010101010101010101010101010101"
         "0101010101010101010101010101010101010101010101010101010101010101"
         "0101010101010101010101010101010101010101010101010101010101010101",
     FXL_OK, 0},
    {"f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0"
         "f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0"
         "f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0f0",
     FXL_ERR_RANGE, 0},
    {"9f41bd5bcbb0f1d7bda6ec8707d777c6f13fa60de6281c5f78de3f618b1a923f"
         "03bb3768472eeadec46328c3cc12239e9e71202100f8df0135c637f5fb2adf2a"
         "4a50f6328ae0ada0342ef0f7b032f7f7e4624c055c6a2aef254310544dd19a96",
     FXL_OK, 0},
    {"0098adb556104f5ad14e7bb2502f7b78b42d0e41f9f005f3bf5bd867048cc96b"
         "5d6094d702730bb52e9ff4f4321ec13eedd1f17658835ae48640c6761b96bfc7"
         "cc5edc4b096ef2fa173557839c5ceb255746ecb38b174faf514e2dcc14a026b8",
     FXL_OK, 0},
    {"b04fff7b29b80c14fc9988ec67083cbd9858d34074a66b250efaeaa308cd7e55"
         "d63521fbbb90f321a1e5c9691b2b6f5f260fd86b4b2474ecff9eda2bf98574f5"
         "7cb0ba517a464a7867e6251c60d2fd88f52da0ef7fde562e167d4583c88cde80",
     FXL_ERR_ARG, 0},
    {"5c10c9cbc65bb196a908c24e5d8fb4ab47d57c43c5fbb0b74bf4f257a62d94da"
         "02798cc64053ab467649d180a5accc5b5946a458bcf0d46859ecd72cdeddb073"
         "f95df455842487fa2a32d65cefda7a48b114b8abba6a2b9dc7ef9484aaef6b4d",
     FXL_OK, 9},
    {"9f8dc6dda345b8fe07322896709fa62e38c2af2ea1b70afc78fa392a0de4221c"
         "51f72e7b318c096a775961a99c1297343cb7e75f005967f347db68dd1db0d48c"
         "5ff6098c9d4d184b8b8356f3944bf55ad1216b68d090a4895e7724289861907a",
     FXL_ERR_RANGE, 0},
    {"f532f7229b1759d2e4a900611b5390ea9d8a2453a1e0e490606d6efa397e4a7a"
         "f8b56162f6dae928989842bdfb4d7f406a0551f1fb4e7ded49247a061fa89ff5"
         "713e4b0ac822d364037a888f463eef79c8093e7d44d827b8fd494b7e9bfe7984",
     FXL_ERR_RANGE, 0},
    /* The first finding of check 7 (texel values; seed 1 case 96012): AUTO,
     * bilinear, a 1 x 32 L8 texture clamped on v, v from -32768 periods at
     * a vertex: the correction points saturated at -32768 texels, and the
     * 13-pixel span stepped from +16599 towards that, reading texel 31
     * where v crosses 0 at pixel 28 and the map reads texel 0. Fixed by
     * dividing at every pixel where a clamp/border vertex reaches the
     * saturation (setup.c rebase, raster.c). */
    {"b24b3e0d7824fd1e48ecdf6f41ffc2f3dea126187558c99c1995e22a18e554f6"
         "41c2a65f91df70bfe176471d13f961a4de64229b325752531a4ecafea769ad3d"
         "a1c46951b68107652becae01f3b78c8ed98af276bfaa1c59bcb490406c56bb81"
         "3d7fb3ac3426a1037d612859f66e905eb8349ea40a3fc30a9e2c8d20f1523a77"
         "c35c0f7d543b6779b755dc6248148ed6c8056f2fabc15c7a1a44a0a8a3dcd5b6"
         "d24c2455d9bb54e678f99bd930cb15f9ab6e94ce68831ca25de2aacdc3c29e26",
     FXL_OK, 35},
    /* Check 7 with mip levels (seed 1 case 24367): a per-triangle LOD with
     * v changing by one q16 unit; fxl_lod_triangle_q8 halved the
     * differences toward zero, read no texel area (-128 levels) and, with a
     * bias of +128 levels, drew level 0 where the LOD picks level 2. Fixed:
     * differences are exact while they fit int32 (raster.c). */
    {"f57ed4f563d6594052e4143b66a07dc19a9b02f50919508f8b8ddb152960d5cc"
         "02bddf0735647e0506e177884b00c69e909ccea54d3d211e17f84994b904895c"
         "2b0be642e23a9bf6f187f6b9ba43f7f64083b427d33a9243115d454499f4295f"
         "ebe8e1fffbcf7be62f0ba9faa7e019da02123d3e01feff7191151399cf2d6709"
         "bb46b6897d40fca5a9551bf7ba5018ada28ba39b9dbf7e46ecbacec7f463db06"
         "979298cb88247227b9c184b65cadbd7398d97b873ddcb1417a24a43772d7c7f4",
     FXL_OK, 255},
    /* Check 7 (seed 30 case 1890225): a needle, 32770 px tall and 1/16 px
     * wide at its far end, whose pixel centres lie on its short vertical
     * edge; its x gradients were ~2^44 units a sub-pixel and saturated, so
     * affine bilinear read the border (v 111.24 texels, outside [0, 128))
     * and Gouraud green was 63 for 39. Fixed: gradients are kept modulo
     * 2^64 (setup.c); such a triangle divides at every pixel (raster.c). */
    {"44eacd48c7af887e5ee841d558a855ac28a7cdd0ec29abc3771caa5ad948a620"
         "22003d2c772265b0427ddd8dcc7c59f143cdbc128f7b7596cffb47ef69fed3b8"
         "f8859d237f05c0330ccb50df7ba4a40b8de3a34cbdee03df28048fca051626da"
         "100b8c19a5280df2437cfbce91c4fe0aaf5342e707df8e59389e48dd3c5baa9e"
         "45c3443556b626d224c1af079efba6114eb4e5abf5cde827b81eccbca1402980"
         "bcc0c3f3a982fad5cce06136ac60bda710e0f70b6cf340193dd5ffedde3b2bbd",
     FXL_OK, 2},
    /* Check 7 (seed 51 case 4333147): AUTO with a budget of 1 q16 on a
     * triangle whose top two vertices share a row and an inv_w (constant
     * depth along every row): the chooser took 256-pixel segments, and
     * their truncated q16 steps drew u = -450.000682 as texel -450, 44
     * units off. Fixed: the length is the longest whose steps' drift fits
     * the budget (auto.h, fxl__auto_setup). */
    {"bc9d776544b102029970a65c5c45d07e6d97c0c3f305a3916f3d36e735f08c18"
         "daac31f498513d7d3ed4c22e3090c89b1e1a037a72dae61d6b3230ff0626255a"
         "d04b17c8450e9a35779dc30374f19e8545360592e43c6c8abfafb8e572ce38ae"
         "576c020d816c8d38716ed74eb888ced7ecfb0b2150a6fd1004d724a94c90bef4"
         "ade8818e015ed050d6f0e092c4897a8d3be5a1022d4f0bb88ad000db2aaaba5e"
         "6c5b2ab53474793f7dd39e93cc9931418a0609a7c37e58be4c90db98a6f7b3d0",
     FXL_OK, 800},
    /* Check 7 (seed 61 case 6260750): exact mode, per-segment LOD, a
     * depth ratio of 1.1 x 10^9; at the far edge the rebased v (16 texels
     * of range) had no precision left, as exact mode's bound allows, and
     * the LOD measured from it was 15 levels high. The check now widens
     * the reference LOD by the coordinates' error (fz_lod_widen); the core
     * documents it (raster.h, FXL_LOD_SEGMENT). */
    {"c76e3eaf92119a6a336596f334557dccd558a353350bc93c32249974bbbc8285"
         "88ad22ef1420d462a6b10266b90fe08c105b244c4ffa61cdddf65bd64f216083"
         "f05370d04952b4c26e58932171dc77251a120a49c48ad8eaea00069b92bdb4aa"
         "2ece7cd78a8aa5340c918abc9d4bf00d303d5e13b4f3ffac818b8205076e13d7"
         "487f6312e5975e17a595fa856bfd830f3e0f317aa0716c2a4cd41ffe8d9787e3"
         "b2d67c5e5e0d7760d5724c2e5820fa38b75235655bb521b8df6545e595c7d05b",
     FXL_OK, 467},
    /* Check 7 (seed 1 case 123457080563, a review's run): u of 0, -3 and
     * 2^31 - 1 (a clamped v from -2^31), every inv_w equal, per-triangle
     * LOD. The draw passes the topmost vertex first, from which two u differ
     * by 2^31 + 2: halved, as raster.h documents for differences of 2^31
     * and more, the sliver's area gives LOD 3.29 (level 3) where v[0]'s
     * order gives 3.59 (level 4). The check took the differences from v[0];
     * it now takes them from the vertex the draw passes first. */
    {"2bff05b6f0ee617f2bdbfe3778894d763fbf387ff1558c8f5d85f60cdefb4012"
         "d728013477ffdc9d3cd0559c1dd43e1048117bc0e3071356eff48172d6a1883e"
         "61ed20f044fc657965cb026b9ad213dd7c93bfa43cc5c9f0e7d2194c9a0b9e48"
         "8d79fc0758de5940f6a08e391814481f94bfbc0dff81b1907bd517036737a201"
         "1ac6124f9c7467f3abaf7b36be5a4d55f39ae76c15268b510592a7b1cab05fb2"
         "85097696e5bf391d9ea7420d341058f709b0e45cfa5830ae8f7ce4d6fbd59af8"
         "7afc7daa669246cba54e9d2b22cbc0f0c685dc626f7094d80c86da76e117da58"
         "7441c8d223b99f96c8e21edb7024f768cb0626dbb7f39c5fefbf598ead5b1450"
         "19d6f22648957e3f82effaf26317eb4c26c961e74165cea4a5264d29defc8c1e"
         "22fa2595b6a7f5f900a28d9ae2dd7ceaf9a24ce19c2e85e88423eb839f2daa6c",
     FXL_OK, 3},
    /* Check 7 (seed 58 case 77738644): exact mode, a 49,000-pixel
     * triangle with inv_w 1, 1 and 142 and v across 32,768 mirror periods.
     * Its planes are anchored at v1 (smallest inv_w, then topmost), 49,000
     * px from the pixel 2 px from v0 that read v 0.047 texel low; the
     * check's bound measured the planes' rounding from v[0] (0.044). It now
     * measures it from the vertex the draw passes first. */
    {"c07fd14f75560e7bba3a3acbad8dac8328a5d722f6a62033ecfb58cffd61dee2"
         "369b769e348a27c28f222d48e577da338dd46c4bb16e3ef53ab3f66d44c07ca0"
         "fc26b474b322073afcd3913f8a8e5ba0c82bb7343db1a3e7434e8d8920260fd9"
         "5be80b7fb37e617e3f522be57925a5115d6b4b0da58077734945d7f041e16de1"
         "d3eec6e530db036a046ecdcca7e5fedceac3fd9f83a1551a7bfd78ea51fa3640"
         "a7969115fbfe7c5fc2cb0bba9e8a9986922613eec70894d5a717f1bc9d8e7bd7",
     FXL_OK, 10},
    /* Check 8 (depth values; seed 61 case 21054, found on the core before
     * the fix): subdiv 32 with depth, inv_w 2^21, 2 and 2^32 - 21. Where a
     * one-pixel step of the depth plane reached 2^31 it was saturated to an
     * int32: pixel (240,-373) stored 0x30B7 where inv_w >> 16 is 0x0B0F.
     * Fixed: depth steps wrap modulo 2^32 (span.c, step_z_pow2). */
    {"7583170d52121da0e01593c0869b61bbeaacd5e0f36709b36eabaa415d5e1983"
         "ae52cdfa330b842ce2f84ff3655a8f609293da37ddec4ab427c5d9140f9555c4"
         "068a5dc89330b57b0fd6b6c271ae510e12010f50613a2303ed9e7a0bdc74f05e"
         "abcd507c1f14efebe936a14626cf01b98b73b6397320e5f2847516b7583fd294"
         "6acf3aa06ba114cc8f7837de485d168b1a6f167495de506e21a02dcec49fe553"
         "30e83218c7e09182c16b758b96ee6ded49f37212e6f56de6fefca2ffa42bed70",
     FXL_OK, 18}
};

/* Front-end inputs (fixel-fuzz gives them FZP_BYTES bytes), recorded in
 * the default build from seed 1: one of each kind of outcome. */
static const replay_t pipe_replays[] = {
    /* draw settings refused (case 29 of seed 1) */
    {"029d2b6b7ee459ef90b52e0c1606afbee2dc2d49f73afc5d4b42634e4f62d6a2"
         "8e667a2f9a6bfa5a32f3a38f7b234835bb35d109cadbff12319e6d01737475e7"
         "3d8635a5751d6f40c527b4966ee2a128243ff0d8b7466aa8e2d3180e03ca3448"
         "068e5c1496fe24da91e1287bb3a9e94f5dd4a0272e4dfa439c8830b72e245ba1"
         "5f2e5a5f57bc56ffc72a7020e0d6517ec6d4622aad57b3184ec7186cac9cfa33"
         "c9bea6a7852311d4f969eef3ca25e97f91b5a41fda585c4bb54f46b4abc9a942"
         "607847164a2cab48540a12e2b73941feb245c779790d17266cb731a62eeec432"
         "b149bae877c6bafdb3033833566d29ec8f88bb3ef06ab377472294896953c598"
         "db251c5e0cdd3af5e70ccfd86cf2f1436296f24d3c2266175534d8897d8ce071"
         "14362608abe3e2d42758ca4059aa62db2745d56437296813bf7c20600a91a129"
         "dfc8c030db9f28b8cc88e348b28abb8655e879f7affffbb41f42cb728d3979c8"
         "ca1e21cbf9c499d1a04deeccd90fc7f33b21d64b9772ca37ca132fc961fa1b56"
         "4a259165beba1046aa1a7a8970d71f725ee16c245d408d15896a9fed0b5e9be4"
         "eab8cc21cd794222615644b32796d096201194c0a26e0356b95dca76badfcc42",
     FXL_ERR_ARG, 0},
    /* bands, depth, swapped (case 123 of seed 1) */
    {"faa99bbacb5c90e175d1d0737fbd10dc5f69f986bd3e168cdffa5743246db292"
         "aa0268f79b3656876e0f9b80a22fb5039ef3038de4184580c41e3de44bc401aa"
         "303857ec6f22525b2f3bbcf73366ef0bc47d3e44ce3c4c514fea255191bf41f0"
         "3378f738aace0c6d0fa3e513c58f6f4a97167320a509174028df8c96ff1902ab"
         "8ddc9528abd09b702b885e1c5c54b68078986cff96b6c346635fea13d7f4bf5c"
         "d667d2e47112cee5e9eb225521f73a62785d5aa2363c2a92b13f6c90f46c3186"
         "4fc4ec149738b8ccaf0b8be385152147b9c2ba00b29030bb99e7003f3102d2a4"
         "33c3c8338ef05cd908a91305cb6962466e8481b8579674378710951fd401931c"
         "bd3c9a8bd200b3f93358a7cb47ae956cfd5ee1cb24f9fa67889ec824588fd00f"
         "e8f41120f2d19eb33b2434f9ab6610933d56d56ad31163984774044e561e7f46"
         "f0ac5e3e3a935298538737265135e7423a95971a504f5d510186e20416b49dff"
         "d02174bcebab0956c87c3fce4393dd8afa3a5d21bd8fb6d26f1388c2f03d12f3"
         "78c7d3956c430bf9dbfd42b2761115cd1f0b20226d6ce4a3f38489fbf805b5d9"
         "d28aee4cd93b3b0a80f6e0da561e3330aaa0ee2ae404d4d3ec10d7ab70b78786",
     FXL_OK, 842},
    /* ARG from the pipeline (case 157 of seed 1) */
    {"c9e321dd4eda45b262e5310ba7162d99605016c143f2a70f326587cc93a5af49"
         "5f2f9fe0005bf7bfdd6b536f5ac71a1ca3d4f80a81fb23845d9e977ef9846316"
         "37819f482002d9cdc0b9066377fe6642321d8177244e32f11ee7170aced3f6fe"
         "b2c301bdddf34cf18126106765c326ff5ad4e043328c2b3a6737ff17c8af59ea"
         "d6488979dd5b27e5ee409c05ee74d8fbf3b8e7eeee47bdb681e6c126c1643501"
         "a0bfcc9a3a6ab7301d53ec733293900e2a4b69ad44a504017375919c435cb445"
         "481831db084006866e5980f90a4cd7e66f9e2e7de28db91f088648e0dd5b4b28"
         "c97e737a2ac7f4623908fcb0de0041671d17a3b1b23ab63fe2821573386bf621"
         "20e79ce19c2d6d1d345167bf2e8b68e3be53881cf2926e0ca9094cf51a05789d"
         "ad3065566b30a475fd71f3de60e68e8a3666008102c701dc1296ede701ae0332"
         "65f9a4b20e03955281e100a132c339f3063dbe67d7a2167f4ab3b97e81188634"
         "4460e12253ae9b4b29fc6df36889c4ba71a7590116b1bbdb7ee0fd3b652b0935"
         "8c61dc6cc0acb6242c3331e25e82c2de046ee0d1fd7be1968080bdbda1c2a225"
         "247d5f9f1ed6c3b7cf9bcbf029a25f4c6462f878e620ef401652250a5eb43a45",
     FXL_ERR_ARG, 0},
    /* 65536-vertex mesh (case 392 of seed 1) */
    {"1b5b05917f5154f4988cdaed78f00108e64a1c78d1e2728e917f124d97b71ce9"
         "6173f8fffb9623051d320204827b4249ea935e529374817396475a226bdb4dbf"
         "672e57c9d12bfacb5409b245d5f4aea71f0d1c6340b4a100e5f4f64e0b8c74d1"
         "2232ab36d0b7caf2c081295f77df6df80bfc10b8e7c6111714c296072da6b50c"
         "0efcf9eda268a4304b8da4f4bd0232043c0aa786251fee8df40967fa5b17844a"
         "0db0f4def9ee940c4d1f10e6de67f47b96a7af09eef7db15926db73256f98041"
         "22abc5d094f3b5edb759cc11db059da1b5a19a29235a13fc61a1197512842c4d"
         "90dfba9b5d9f00cdffec956b68db5af02426d16a78be231991fb8868d51cd7ee"
         "02c451089c951edc59ecaeb4cc62b0e08b4df4c0fa5e0d296cbe21880e1a3be7"
         "92f29b89de94e88cb7515b17d5ca790bdab0f2b25b98f69f3524e2de7768aa6e"
         "881abebb35028d66f0f8c709876f966622dc1157d1d5fddf225db4dd0a6e3382"
         "f2ab68b1784edb4f8d41325e18d96338be81033cf9cb9097809038e024f2bb71"
         "7492156c2892cbb68b42c0a9277363c18fd928f8a00946436f6ac6a30e6da851"
         "3962d964be2797b404de85e6bc8b5dd69986109927423b9d0fa1f8cb1bc41e41",
     FXL_OK, 0},
    /* index out of range after drawing (case 627 of seed 1) */
    {"1b8e06ac5f8a639a42aeeed1450246c116e4560b5b83e3164fb4161693bdecb3"
         "277f3bc8bef734744514762ed252d216cd7789c5afedb3391a115674229fa963"
         "26dccbbc4cb0f0f2701e8046ef4ab5e5bd7b73bb970975afd9cd3991dd06d8c0"
         "9b20cf2f042a5cd4769b9110b3d2fc8b32ff077bfc540e5a34a664b7b3d8333c"
         "e5150029544a6bf75e6e226d87adfa846754dc9350043f8b5306c9c3e9ba6d0c"
         "b96b1bf8bb66b544270015a7abaf3b648a355bb2bd1ed5cab02c232348c44444"
         "2a3f41182b70bdef6cabad04a1c6b31fe016f5ecb85978e527df30c11ca177f2"
         "3b8b5252f91b1ce5bf4351ef4ba32b5b9f5f1c31258afbed3c7b92a4b63cdf0b"
         "3f707b6f1f8f81dc16785d0115491e9d80c12588a67426bc5310729e59b7662a"
         "0a0afa6f533f37cb802b65f601707b718538745561101c6fecd667b54269f7e6"
         "77880c89f2fd15f7daf46e121881baf69f5b47f31f5af525f5c8765e7dc9c6ed"
         "e3a279b209e3755a0c92a78844dbc98180a30b9701adf5542385a2331e526afa"
         "8bf4afabdeffb001f5f78fd6dd0b15d2242e4b062f9343e0fd85bd043996bbe6"
         "9dbedb1b088cb29197ed1d9de4be532f8cb81843e47208c40490c21c9c303e44",
     FXL_ERR_RANGE, 5},
    /* matrix overflow (case 1688 of seed 1) */
    {"771022e02294ee01eecfd75a7051b5cda1fbd013c3a1be3e5113b2a41dd2c96a"
         "2dd550608618a99e2b01f3bf3fc2b516e53a5d2341ae03e62962c858d88be9b0"
         "c450e82a7a494f5a73282dfa5dddd704bb0762afe080015236be499951a40495"
         "5665836a59849276d88c443e36197d85d006f4a5ed49ab9a8a38172b30cf4347"
         "9ed975c3915fc00704eb3808d40fafd467cff4270a48405cb08ec38cb7391a45"
         "2fcd068ed0fa6aff683d4d40fe06f4dde6efa3d25c3a2ff486dc983c3b851e42"
         "4c6e15969e9630608a1d9d40bae4bd6889c19faa6d841fecd62d526d851ad8e5"
         "096da8df0859e8971a6504af3a583163dcd991f8e3a46051f735ecc303b7b234"
         "84f762b8fc31d5405dce8b8a4bfb30644d24d4e846f7c12d04950a6b082f0f07"
         "ba3c3e4f6086afa3b3039b28abd3b1d330890ac0678770cf39320540108479a2"
         "490f35f8f240da1926894b50171dd35b32da7d754e3aa801541f0d64d432d56d"
         "dc71186e9df32df34d6f2614a3f3cd8b60ae62e28308820ddbe38afafdffefa8"
         "7edbf6bd7ede1a20a9be08130c8547300434b677742d269bc51946d5f5c18aec"
         "45909ffbd8b08f2b13e434e6685ccb77879d0d784e6734037e7e3c8bb2473142",
     FXL_ERR_RANGE, 0},
    /* guard-band clipped, tiny near (case 5668 of seed 1) */
    {"45e695710c54da8498f36f5fb5725909d2d50ecee3d344e2c3f53eb5832df207"
         "b2ea0250395358bf40967dc01132352a64e0d6f1f1411a7ae85e9c9b7839f784"
         "2e79bd286b21efe83d45bc41076976caa448e22fff765a40bfe819b2bd4f5023"
         "ca8e1d85bfa9457882282397bb728f7b636f8e49706d5bf8d00d251dac5465b6"
         "61b4caa84534dc074320b7b0ac6c1203e7abc5a38ce8ae5b655fa965bd80dade"
         "8fbe046b0d7db47bc326ed398effafce092e5054d6917e4c58b6ab51e7b3aa46"
         "fcfcf785899fca66821e858a351628f7d0c15af78bd5ef9b30521e85471e2e5b"
         "cc96ec5d573c8b4d96ac59d21288f2c5e1118d83f0ffadc87aa567bbf78305ea"
         "42cb08967b9bb142386fc0724cd50576edb50917b44a489d2f10e594b34e60c6"
         "aba03fd5877ee9abc087542699eafc9459714c6dbf65d0eca0d78555d72872c0"
         "4a717edb26e900c409dfcabf179bb366f03539ae11da2c61ebb850f0610503c6"
         "42dd7a9b24b2656367fbed5abc06f4ff62a937529d4630307cdf4fb44989d125"
         "a2f79b8ceea57a288c1d1ccb93f110ba353d8236830d5d362fd1720952560ee8"
         "b3e1133e94930046af7c777799fff3dcffc61246faefbf39c3ab88c67bab3b46",
     FXL_OK, 161},
    /* lit spherical texgen, cache (case 13183 of seed 1) */
    {"38b9331eefc2bc06edbc19d0d13d50ac1dbec94c3a7bc474b1262fc3ad76678f"
         "b43edfdeae6aee0ec8048ae57f1d87da45cfc7b41dee3104b11a9c5b0af67ca3"
         "860f99d8253dd9c6de9faa56e754b60e046339dfcbbeacb07a20a35c25253f61"
         "a8a53df72f4db4c5193a0d81de877a6fc71abcc020b8fdccbd8b8692c6228304"
         "bd2d125caa0663b5eb13a3c26a5b8c0df6e8fd6d26c56b3a17adaa541519ad8f"
         "d40073e46f80c9795883df1daf8c512f3f99f5ae1f2c3c6e0d6ffd8b47565ac2"
         "02eb4d5006e9d9473f997fbb0df5cfef5f63519542d90d81beb32d9972440753"
         "c692f3c3b6a67169a6a953c78380e3a16436e313760d9c90bd3271a16dfeeb74"
         "26617a7bd34268adacc9e640dd13f70a30073085a906abd6bba24be0f0b44838"
         "5eb1b65f268e86a459b564fe3f86fcaca6f07f2d046e21d94b638711ba376d96"
         "b79ca920975dbf1988f9e86b3d521deac263d7743c1761f8ff362e37fe7d453c"
         "d62f575ceff68a2875c8891ddc02338891b3f93563255db6335466c9a0e0fcfc"
         "2c83fbd35c8cbb325fef006069bba5a6342383e346138b9c756383541982fb10"
         "563b9d4f740d34e9f730566b265d5fafd48d8ed7ee63e5c0ce2c43816c8f95c2",
     FXL_OK, 26},
    /* the three front-end mismatches (comment at the top), found with
     * -DFZP_STRICT=1 before the fix. rotate_axis(0, 65792, 0), |axis| =
     * 1 + 2^-8, was FXL_ERR_RANGE (case 1738 of seed 1) */
    {"718ab3bdfbdf15144873f494886208bdd37eda65b9028d8f93ed822eb1c9303a"
         "90d8a2eebe46e313331dfb2b24d89f9fea2f1451b41ba2e8a6264b3838964fa3"
         "8ab548e85b54631c0872a3dead4333d0bff20bb6de4bc2a5981b72d8cc849a6c"
         "f0670a7b5b85a4b22dbcab1e9718b5f2624dde0b42a2ca90a76c0154464733ef"
         "8fd7bce99c3fd274a77b529efc8dd9780632789f5a0afa3de9d75594ba0caebb"
         "33236d1710ce496180b5be5266cf8d797d02e7ffb7db84c9a24e02b77a1b13c5"
         "f4397aa2ef8037f4127bd463bcdebf28d08d45387f141525f085f76cd799a301"
         "3116ebfffd6201e15949bbb74888e19baa12757e1a91a159e27988ceb1850a79"
         "a4ca5dc99f49166a1c61cf360575ad9b684b300683ea0062b7e8fd484d185a42"
         "07932c323f9300dd333bd8be63a21b779e2159a89deb7421a541602af4d33056"
         "f81c7e4d988453790e5b9a879fa2e0b0322197e0138ea490b7e7859199460bd0"
         "c64fe48bf8b4a6f457af61732ea41814018f6ddf86b6d86e1361f907de4d80d6"
         "4f7efd62db86fc3658cff7c9393d33d9e4015c9163199d5042ffd8d8742f85b2"
         "0169823f8f453d41ca4cd5990cc59a7c7b84d608bef2d517fb7bcd38f386d0c5",
     FXL_ERR_ARG, 0},
    /* transform_point, fourth row overflowing, was FXL_ERR_RANGE (case 536) */
    {"cdd4026927419ec93c2211a598f290dce834d2c58e01e0c6e87036cff45b4805"
         "605bfd425d620a6076649863a7b6faae227b24abecb6892df5af298817d8d3d8"
         "cd6571f8c769a7587eaa85f52943f6cdfa21d3223d7a1b9bf78244f81b4f19b6"
         "24b97d826a4855e0efc7096d2d1b1de5c2b12ea75e4e143dfc022263f27ee267"
         "a41597837df7ca0c767c28a0c46188d0641d2813f05808bfe11ab8534879297a"
         "30c21804d9fe8aa33f1f7bc5b52aca96b263e0f712b6dd171b6cb0ec5fae4844"
         "b62ba5afad3d9b3456a670b32e32df9b83b9956fc1fb8f0200f76cea50a5a008"
         "82dcf1d70a4cb1dccffa354d0c94443efe3ca8ea863d38f5c8cde04f63649b8c"
         "b5c14e6908f22df00763b1d0578d0745b0ca6a8b3a62d3288fb0a13c3b90dfcd"
         "7b246b6f89dc24339ac6cb20597dfe9ecfcd38d2a00b9dc2019cb8b2f1208173"
         "146ef34fc7f0052deb0e166e91ba53e4a65c3261000cc63ac749eef3f823d023"
         "51a1841fe473d4b765bd01a1742407746ac63d28a26dd453507abe79b7bf9b2a"
         "96c11d3263680ef80131bf8f0fa11068035fc355ecd31f2f6960d9dd70de5af7"
         "8a0aac46587668d9734ccfbcef103e9f0458fdbeaec89d1d0b295ac56f6e2a44",
     FXL_ERR_ARG, 0},
    /* transform_vector, the same (case 13386) */
    {"19ac6e751ae0ce57215353131a0679848b1aefc0d0694dce88c1f04e310e209f"
         "c6c88094c085c8451f734e3036fe662deebf61e238beb22da943b4f71c836edc"
         "d1a6054fa74f22695c7e4445ea0568088dc4181852b642a3eeabe714f0a80ae2"
         "62b931a93d53f2d43ef520eae26e02529250e908f688987961f95233de8fc571"
         "6e93a5ec23bcbf3b0dd09e27f3d8dfdd0c9e9ace69af435f7a7950185a3d09a6"
         "c5b822b6f8f1ae60540aaabf84ab5f21b14027814ed109553a594129ba1c0347"
         "70a396f52381902d41ecb02cc6c44cd5bd494f3d2bd7ac61a1f5a7ee2f4efaa2"
         "e09ae14f82f66425174fd0461fdb225ff24845c1c3a3b8628c8089e71d0e96e8"
         "336da3439ba9d76a9ac2a07c6a4bbf7951c9681421dbc83c76653690b155e31e"
         "5fa1c506d82e73e95f875a8a062f40e3518f0a45de3d906eea10e3c80dbd3505"
         "9ef55e64bc651a2ddc25bed956fc8ff80d32f53c537a3dee39b429a32284a008"
         "d1dcdf57f959e8e7523097110ea6664ea1a1beb4f570139ec5acca10a58b7355"
         "6df1c021c85b41c9a048d33ea4f91aa991dfc3e0d1e198d043653919ff69c3b3"
         "5983e0673a8a7fd87dc6bb50dd3224e16c989f148db49471a68ef9a9e2aa4847",
     FXL_ERR_RANGE, 0},
    /* set_perspective(fovy 1, aspect 1, near 1, far 0) was FXL_ERR_RANGE
     * (case 5076) */
    {"b384554af7c406acae422b3559c1f9b7330f62d3eb894fb260a115ac158860f6"
         "2e1bb5c4e0c7b8e4a83f7fc8cedd31dcc09470147b0eb82d05f1ad8a4fa7e59e"
         "2fd727c03cb60940f71bceb0b24e0e1d97ee8d56c403d3840be7f7194003633d"
         "83c75b7f263eb2f2a6e33531f9baf2d9ff3dc7a64af9081ffb085bd0e99f66c8"
         "97c8625f043cd56d432f01dabe5245dd4d3a0863af1702f6bda3c1bcc878ad13"
         "61b39aea9c1dd13d7f9fd6e71d03697d4f96cf25df7b1a8a3cec0f2f2792b284"
         "dc639cf36b817787be12361905fd9505e5715751b3061f72c198ecda568cdeac"
         "bbeabf5c7b1138e5a4f900790d40b769e03a9e3944c24d3a1dce28687726c479"
         "ed612b076c5acc9fb55e735c502601882fed76bd95c907648848529fefddf99b"
         "cc1911fa6e331e633987ae9ff4f9d3c7bd02dbeb232a83360a1f360d98b9265b"
         "c83c37b1ce38cfafdab50f8c3b569a775fa6670977d03c0fa351d64a6b974ce9"
         "ac8ac11645ff97005054a9a8b683c09e889a075223723f08e63b62e1e647d55f"
         "db62bdf1fc51295f71a4e8dfe3e8d91a7eddbc99e9e1517ffae1fefb7a8855c7"
         "da4b6cfc45b2284a04e9ca8eb01e5f9b81c65543ed2e319e7368b42732c5cd84",
     FXL_ERR_RANGE, 0}
};

static size_t unhex(const char *h, uint8_t *b, size_t cap)
{
    size_t n = 0;
    while (h[0] && h[1] && n < cap) {
        unsigned v;
        sscanf(h, "%2x", &v);
        b[n++] = (uint8_t)v;
        h += 2;
    }
    return n;
}

/* The checks of one replayed case, raster or front end: no finding (msg),
 * the status want, and want_written pixels (< 0: not checked). */
static void expect_outcome(int bad, const char *msg, const fz_outcome *o, int want, int want_written,
                           const char *what)
{
    char m2[FZ_MSG + 120];
    snprintf(m2, sizeof m2, "%s: %s", what, bad ? msg : "ok");
    TEST_ASSERT_TRUE_MESSAGE(!bad, m2);
    /* the recorded status and count are the default grid's (replays run
     * clean on any grid) */
    if (!FXL_TEST_DEFAULT_GRID)
        return;
    TEST_ASSERT_EQUAL_INT_MESSAGE(want, o->status, what);
    if (want_written >= 0)
        TEST_ASSERT_EQUAL_INT_MESSAGE(want_written, (int)o->written, what);
}

static void run_case(fz_case *c, int want, int want_written, const char *what)
{
    fz_outcome o;
    char msg[FZ_MSG];
    int bad = fz_run_case(&st, c, &o, msg);
    if (bad)
        fz_print_case(stdout, c);   /* the decoded input, for the record */
    expect_outcome(bad, msg, &o, want, want_written, what);
}

void test_fuzz_recorded_inputs_replay_clean(void)
{
    size_t i, refused = 0, n_replays = sizeof replays / sizeof replays[0];
    char counts[160];
    for (i = 0; i < n_replays; i++) {
        uint8_t b[512];
        fz_case c;
        char what[96];
        size_t n = unhex(replays[i].hex, b, sizeof b);
        const char *need;
        fz_decode(b, n, &c);
        need = fz_left_out(&c);
        snprintf(what, sizeof what, "replay %u", (unsigned)i);
        if (replays[i].status == FXL_OK && need) {
            /* A valid case drawing with a feature this build left out is
             * refused and draws nothing, culled or not (a recorded error is
             * found before the feature checks). */
            snprintf(what, sizeof what, "replay %u (needs %s)", (unsigned)i, need);
            run_case(&c, FXL_ERR_UNSUPPORTED, 0, what);
            refused++;
        } else {
            run_case(&c, replays[i].status, (int)replays[i].written, what);
        }
    }
    snprintf(counts, sizeof counts, "%u of %u recorded inputs replayed as recorded, %u refused: they need "
             "features this build lacks", (unsigned)(n_replays - refused), (unsigned)n_replays, (unsigned)refused);
    TEST_MESSAGE(counts);
}

static void run_pipe(fz_pcase *pc, int want, int want_written, const char *what)
{
    fz_outcome o;
    char msg[FZ_MSG];
    int bad = fz_pipe_run(&pst, pc, &o, msg);
    if (bad)
        fz_pipe_print(stdout, pc);
    expect_outcome(bad, msg, &o, want, want_written, what);
}

void test_fuzz_recorded_front_end_inputs_replay_clean(void)
{
    size_t i, refused = 0, n_replays = sizeof pipe_replays / sizeof pipe_replays[0];
    char counts[160];
    for (i = 0; i < n_replays; i++) {
        uint8_t b[FZP_BYTES];
        fz_pcase pc;
        char what[96];
        size_t n = unhex(pipe_replays[i].hex, b, sizeof b);
        const char *need;
        TEST_ASSERT_TRUE_MESSAGE(fz_input_is_pipe(b, n), "a front-end input");
        fz_pipe_decode(b, n, &pc);
        if (pc.c.has_tex)
            fz_place_texture(&st, &pc.c);   /* an I8 texture has no palette before */
        need = fz_left_out(&pc.c);
        snprintf(what, sizeof what, "front-end replay %u", (unsigned)i);
        if (need && (fz_setting_errors(&pc.c) & ~FZ_E_UNSUP) == 0u) {
            /* fxl_mesh_draw answers fxl_draw_check's FXL_ERR_UNSUPPORTED
             * before any vertex work, whatever the pipeline would say */
            snprintf(what, sizeof what, "front-end replay %u (needs %s)", (unsigned)i, need);
            run_pipe(&pc, FXL_ERR_UNSUPPORTED, 0, what);
            refused++;
        } else {
            run_pipe(&pc, pipe_replays[i].status, (int)pipe_replays[i].written, what);
        }
    }
    snprintf(counts, sizeof counts, "%u of %u recorded front-end inputs replayed as recorded, %u refused: they "
             "need features this build lacks", (unsigned)(n_replays - refused), (unsigned)n_replays, (unsigned)refused);
    TEST_MESSAGE(counts);
}

/* A valid 16x16 target (in the RGB565 byte order this build draws),
 * untextured flat draw without depth, full clip. */
static void base_case(fz_case *c)
{
    memset(c, 0, sizeof *c);
    c->w = c->h = c->stride = 16;
    c->format = drawable_rgb565();
    c->clip.x1 = c->clip.y1 = 16;
    fxl_draw_defaults(&c->draw);
    c->draw.depth = 0;
    c->draw.color = 0x1234;
#if !FXL_HAVE_GENERIC
    /* Untextured draws are left out: a 1x1 RGB565 repeat texture (a random
     * texel; fz_run_case counts written pixels on two backgrounds). */
    c->has_tex = 1;
    c->tex.format = FXL_TEXFMT_RGB565;
    c->tex.levels = 1;
    c->tex_seed = 1u;
    c->draw.texture = &c->tex;
#endif
}

static void set_v(fxl_vertex_t *v, int32_t x, int32_t y, uint32_t inv_w)
{
    v->x = x;
    v->y = y;
    v->inv_w = inv_w;
    v->u = v->v = 0;
    v->color = 0xFFFF;
}

void test_fuzz_int32_extreme_triangle_covers_the_whole_target(void)
{
    fz_case c;
    base_case(&c);
    /* (INT32_MIN, INT32_MAX), (INT32_MAX, INT32_MAX), (0, INT32_MIN): the
     * target (0..16)^2 lies well inside, so all 256 pixels are covered. */
    set_v(&c.v[0], INT32_MIN, INT32_MAX, 1u);
    set_v(&c.v[1], INT32_MAX, INT32_MAX, UINT32_MAX);
    set_v(&c.v[2], 0, INT32_MIN, 1u);
    run_case(&c, FXL_OK, 256, "int32 extremes");
}

void test_fuzz_inv_w_zero_is_range_error_and_draws_nothing(void)
{
    fz_case c;
    base_case(&c);
    set_v(&c.v[0], 0, 0, 0u);
    set_v(&c.v[1], 16 << 16, 0, 1u);
    set_v(&c.v[2], 0, 16 << 16, 1u);
    run_case(&c, FXL_ERR_RANGE, 0, "inv_w 0");
}

void test_fuzz_invalid_draw_fields_are_refused(void)
{
    fz_case c;
    base_case(&c);
    set_v(&c.v[0], 0, 0, 1u);
    set_v(&c.v[1], 16 << 16, 0, 1u);
    set_v(&c.v[2], 0, 16 << 16, 1u);
    c.draw.persp = 3;   /* not a power of two: raster.h FXL_ERR_RANGE */
    run_case(&c, FXL_ERR_RANGE, 0, "persp 3");
    c.draw.persp = FXL_PERSP_AUTO;
    c.draw.auto_budget = 0;   /* budget must be > 0 */
    run_case(&c, FXL_ERR_RANGE, 0, "auto budget 0");
    c.draw.auto_budget = FXL_Q16_ONE / 4;
    c.draw.filter = 2;   /* unknown enum: FXL_ERR_ARG */
    run_case(&c, FXL_ERR_ARG, 0, "filter 2");
}

void test_fuzz_sliver_thinner_than_the_grid_is_culled(void)
{
    fz_case c;
    base_case(&c);
    /* 1/64 px apart: both snap to the same 1/16 grid line, zero area */
    set_v(&c.v[0], 0, 0x8000, UINT32_MAX);
    set_v(&c.v[1], 16 << 16, 0x8000 + 0x400, 1u);
    set_v(&c.v[2], 8 << 16, 0x8000 + 0x200, 7u);
    run_case(&c, FXL_OK, 0, "sub-grid sliver");
}

/* The front end over base_case's target: the default pipeline of a 16x16
 * viewport, no culling, and a mesh of the vertices given (z -4: in view). */
static void base_pipe(fz_pcase *pc, const int32_t (*xy)[2], uint32_t nv, const uint16_t *idx, uint32_t ntri)
{
    uint32_t i;
    memset(pc, 0, sizeof *pc);
    base_case(&pc->c);
    pc->init_w = pc->init_h = 16;
    pc->cull = FXL_CULL_NONE;
    pc->material = 0xFFFFu;
    fxl_texgen_defaults(&pc->texgen);
    pc->vert_count = pc->npool = nv;
    for (i = 0; i < nv; i++) {
        pc->pos[i].x = xy[i][0];
        pc->pos[i].y = xy[i][1];
        pc->pos[i].z = -4 * 65536;
    }
    pc->tri_count = ntri;
    memcpy(pc->idx, idx, 3u * ntri * sizeof idx[0]);
}

static const int32_t quad_xy[4][2] = {{-65536, -65536}, {65536, -65536}, {65536, 65536}, {-65536, 65536}};
static const uint16_t quad_idx[6] = {0, 1, 2, 0, 2, 3};

void test_fuzz_front_end_quad_draws_and_matches_the_indexed_replay(void)
{
    fz_pcase pc;
    /* a 2x2 quad at depth 4 under 60 degrees: 2 / (2 * 4 tan 30) of the
     * 16 px view, 6.93 px a side, centred on (8, 8): 6 x 6 pixel centres */
    base_pipe(&pc, quad_xy, 4, quad_idx, 2);
    pc.cache_mode = 5;   /* a vertex cache of vert_count entries */
    run_pipe(&pc, FXL_OK, 36, "quad");
}

void test_fuzz_front_end_matrix_overflow_is_range_error_and_draws_nothing(void)
{
    fz_pcase pc;
    int i, j;
    base_pipe(&pc, quad_xy, 4, quad_idx, 2);
    /* view and model all INT32_MAX: each view * model entry is the sum of
     * four products of 2^62, beyond int64 (pipeline.h: FXL_ERR_RANGE) */
    pc.n_model = pc.n_view = 1;
    pc.model[0].kind = pc.view[0].kind = FZP_RAW;
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++)
            pc.model[0].raw.m[i][j] = pc.view[0].raw.m[i][j] = INT32_MAX;
    run_pipe(&pc, FXL_ERR_RANGE, 0, "matrix overflow");
}

void test_fuzz_front_end_index_out_of_range_stops_after_the_first_triangle(void)
{
    fz_pcase pc;
    static const uint16_t idx[6] = {0, 1, 2, 0, 2, 4};   /* 4 >= vert_count */
    base_pipe(&pc, quad_xy, 4, idx, 2);
    run_pipe(&pc, FXL_ERR_RANGE, 21, "index out of range");   /* the first half of the quad's 36 and its diagonal */
}

void test_fuzz_front_end_tiny_near_plane_and_eye_plane_crossing_clip_cleanly(void)
{
    fz_pcase pc;
    /* near = 2^-16 (the smallest q16), one corner behind the eye: the
     * near plane and the guard band cut it, nothing is refused */
    base_pipe(&pc, quad_xy, 4, quad_idx, 2);
    pc.pos[2].z = 3 * 65536;
    pc.has_persp = 1;
    pc.fovy = FXL_ANGLE_DEG(60);
    pc.aspect = FXL_Q16_ONE;
    pc.near_q16 = 1;
    pc.far_q16 = 0;
    run_pipe(&pc, FXL_OK, 121, "near 2^-16");   /* measured */
}

void test_fuzz_front_end_null_positions_are_refused(void)
{
    fz_pcase pc;
    base_pipe(&pc, quad_xy, 4, quad_idx, 2);
    pc.pos_null = 1;
    run_pipe(&pc, FXL_ERR_ARG, 0, "pos NULL");
}

void test_fuzz_front_end_uint32_max_vertices_take_index_65535(void)
{
    fz_pcase pc;
    static const uint16_t idx[3] = {1, 65535, 2};
    base_pipe(&pc, quad_xy, 3, idx, 1);
    pc.vert_count = UINT32_MAX;   /* entry i is pos[i % 3]: 65535 is pos[0] */
    run_pipe(&pc, FXL_OK, 21, "vert_count UINT32_MAX");   /* the quad's first half again */
}

int main(void)
{
    UNITY_BEGIN();
    if (fz_state_init(&st) != 0 || fz_pstate_init(&pst, &st) != 0) {
        printf("cannot allocate the fuzz state\n");
        return 1;
    }
    RUN_TEST(test_fuzz_recorded_inputs_replay_clean);
    RUN_TEST(test_fuzz_int32_extreme_triangle_covers_the_whole_target);
    RUN_TEST(test_fuzz_inv_w_zero_is_range_error_and_draws_nothing);
    RUN_TEST(test_fuzz_invalid_draw_fields_are_refused);
    RUN_TEST(test_fuzz_sliver_thinner_than_the_grid_is_culled);
    RUN_TEST(test_fuzz_recorded_front_end_inputs_replay_clean);
    RUN_TEST(test_fuzz_front_end_quad_draws_and_matches_the_indexed_replay);
    RUN_TEST(test_fuzz_front_end_matrix_overflow_is_range_error_and_draws_nothing);
    RUN_TEST(test_fuzz_front_end_index_out_of_range_stops_after_the_first_triangle);
    RUN_TEST(test_fuzz_front_end_tiny_near_plane_and_eye_plane_crossing_clip_cleanly);
    RUN_TEST(test_fuzz_front_end_null_positions_are_refused);
    RUN_TEST(test_fuzz_front_end_uint32_max_vertices_take_index_65535);
    return UNITY_END();
}
