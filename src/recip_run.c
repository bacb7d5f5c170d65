/* recip_run.c - where FXL_PERSP_AUTO's reciprocal runs start (recip_run.h).
 * Shared by the generic walk and the fast walks, so both step from the
 * same starts. */
#include "recip_run.h"

#if FXL_HAVE_RR
#if FXL__FAST_SPANS
/* fxl__rr_recip's seed for q >> 23 = 256 + i, cached for the fast walks
 * (a load where the division is four instructions a pixel):
 *   [(2**32 - 1) // (2 * (256 + i) + 1) << 8 for i in range(256)]
 * test_fixed checks it against the division. */
const uint32_t fxl__rr_seed[256] = {
    0x7FC01F00u, 0x7F411E00u, 0x7EC31800u, 0x7E460A00u, 0x7DC9F300u, 0x7D4ECE00u, 0x7CD49A00u, 0x7C5B5300u,
    0x7BE2F600u, 0x7B6B8200u, 0x7AF4F300u, 0x7A7F4800u, 0x7A0A7C00u, 0x79968F00u, 0x79237D00u, 0x78B14400u,
    0x783FE100u, 0x77CF5300u, 0x775F9700u, 0x76F0AA00u, 0x76828B00u, 0x76153700u, 0x75A8AC00u, 0x753CE800u,
    0x74D1E900u, 0x7467AC00u, 0x73FE3000u, 0x73957200u, 0x732D7000u, 0x72C62A00u, 0x725F9B00u, 0x71F9C400u,
    0x7194A100u, 0x71303100u, 0x70CC7200u, 0x70696200u, 0x70070000u, 0x6FA54900u, 0x6F443C00u, 0x6EE3D800u,
    0x6E841900u, 0x6E250000u, 0x6DC68A00u, 0x6D68B500u, 0x6D0B8000u, 0x6CAEE900u, 0x6C52EF00u, 0x6BF79000u,
    0x6B9CCB00u, 0x6B429E00u, 0x6AE90700u, 0x6A900600u, 0x6A379900u, 0x69DFBD00u, 0x69887300u, 0x6931B800u,
    0x68DB8B00u, 0x6885EB00u, 0x6830D600u, 0x67DC4C00u, 0x67884A00u, 0x6734D000u, 0x66E1DB00u, 0x668F6C00u,
    0x663D8000u, 0x65EC1700u, 0x659B3000u, 0x654AC800u, 0x64FADF00u, 0x64AB7400u, 0x645C8500u, 0x640E1100u,
    0x63C01800u, 0x63729900u, 0x63259100u, 0x62D90000u, 0x628CE500u, 0x62413F00u, 0x61F60D00u, 0x61AB4D00u,
    0x6160FF00u, 0x61172200u, 0x60CDB500u, 0x6084B600u, 0x603C2500u, 0x5FF40100u, 0x5FAC4900u, 0x5F64FB00u,
    0x5F1E1800u, 0x5ED79E00u, 0x5E918C00u, 0x5E4BE100u, 0x5E069C00u, 0x5DC1BD00u, 0x5D7D4200u, 0x5D392C00u,
    0x5CF57800u, 0x5CB22600u, 0x5C6F3500u, 0x5C2CA500u, 0x5BEA7500u, 0x5BA8A300u, 0x5B672F00u, 0x5B261800u,
    0x5AE55E00u, 0x5AA50000u, 0x5A64FC00u, 0x5A255300u, 0x59E60300u, 0x59A70C00u, 0x59686C00u, 0x592A2400u,
    0x58EC3300u, 0x58AE9700u, 0x58715100u, 0x58345F00u, 0x57F7C000u, 0x57BB7500u, 0x577F7C00u, 0x5743D500u,
    0x57087F00u, 0x56CD7A00u, 0x5692C400u, 0x56585E00u, 0x561E4600u, 0x55E47C00u, 0x55AB0000u, 0x5571D000u,
    0x5538ED00u, 0x55005500u, 0x54C80700u, 0x54900500u, 0x54584C00u, 0x5420DC00u, 0x53E9B500u, 0x53B2D700u,
    0x537C3F00u, 0x5345EF00u, 0x530FE600u, 0x52DA2200u, 0x52A4A300u, 0x526F6A00u, 0x523A7500u, 0x5205C400u,
    0x51D15600u, 0x519D2B00u, 0x51694300u, 0x51359C00u, 0x51023700u, 0x50CF1200u, 0x509C2E00u, 0x50698A00u,
    0x50372500u, 0x50050000u, 0x4FD31900u, 0x4FA17000u, 0x4F700400u, 0x4F3ED600u, 0x4F0DE500u, 0x4EDD3000u,
    0x4EACB700u, 0x4E7C7900u, 0x4E4C7600u, 0x4E1CAE00u, 0x4DED2000u, 0x4DBDCC00u, 0x4D8EB100u, 0x4D5FCF00u,
    0x4D312600u, 0x4D02B500u, 0x4CD47B00u, 0x4CA67900u, 0x4C78AE00u, 0x4C4B1900u, 0x4C1DBB00u, 0x4BF09300u,
    0x4BC3A000u, 0x4B96E200u, 0x4B6A5800u, 0x4B3E0400u, 0x4B11E300u, 0x4AE5F600u, 0x4ABA3C00u, 0x4A8EB500u,
    0x4A636000u, 0x4A383E00u, 0x4A0D4E00u, 0x49E28F00u, 0x49B80200u, 0x498DA500u, 0x49637900u, 0x49397E00u,
    0x490FB200u, 0x48E61600u, 0x48BCA900u, 0x48936B00u, 0x486A5C00u, 0x48417B00u, 0x4818C800u, 0x47F04300u,
    0x47C7EB00u, 0x479FC100u, 0x4777C300u, 0x474FF200u, 0x47284D00u, 0x4700D500u, 0x46D98700u, 0x46B26600u,
    0x468B6F00u, 0x4664A300u, 0x463E0200u, 0x46178B00u, 0x45F13F00u, 0x45CB1C00u, 0x45A52200u, 0x457F5200u,
    0x4559AA00u, 0x45342C00u, 0x450ED600u, 0x44E9A800u, 0x44C4A200u, 0x449FC300u, 0x447B0D00u, 0x44567D00u,
    0x44321400u, 0x440DD200u, 0x43E9B700u, 0x43C5C200u, 0x43A1F200u, 0x437E4900u, 0x435AC500u, 0x43376600u,
    0x43142D00u, 0x42F11800u, 0x42CE2800u, 0x42AB5C00u, 0x4288B400u, 0x42663100u, 0x4243D100u, 0x42219500u,
    0x41FF7C00u, 0x41DD8600u, 0x41BBB200u, 0x419A0200u, 0x41787400u, 0x41570800u, 0x4135BF00u, 0x41149700u,
    0x40F39100u, 0x40D2AC00u, 0x40B1E900u, 0x40914600u, 0x4070C500u, 0x40506400u, 0x40302400u, 0x40100400u,
};
#endif

void fxl__rr_origin(const fxl__tri_t *tri, int32_t dY, int32_t xl, int32_t x, fxl__rr_t *rr)
{
    /* the block's end: runs restart there */
    const int32_t xe = xl + (int32_t)((((uint32_t)(x - xl) >> FXL__RR_BLOCK_LOG2) + 1u) << FXL__RR_BLOCK_LOG2);
    int64_t q = fxl__rr_plane(tri, &tri->q, x, dY);
    const int64_t gq = tri->gpx[FXL__PQ];
    int32_t left = xe - x;
    int n, t;

    /* q at or below the clamp (a rounding at a sliver's tip): one pixel at
     * q_min, as the exact correction clamps it */
    if (q <= tri->q_min) {
        q = tri->q_min;
        left = 1;
    }
    n = fxl__clz64_inline((uint64_t)q);
    rr->q = (uint32_t)(((uint64_t)q << n) >> 32);
    /* u = S 2^shift / q (the planes' scale) with q = rr->q 2^(32 - n) and
     * R = 2^62 / rr->q: a = S 2^(shift + n - 62), shift = eb + 95 - PF */
    t = tri->persp_eb[0] + 33 - FXL__PF + n;
    rr->a = fxl__rr_scale(fxl__rr_plane(tri, &tri->a[FXL__AU], x, dY), t);
    rr->da = fxl__rr_scale(tri->gpx[FXL__PA + FXL__AU], t);
    t = tri->persp_eb[1] + 33 - FXL__PF + n;
    rr->b = fxl__rr_scale(fxl__rr_plane(tri, &tri->a[FXL__AV], x, dY), t);
    rr->db = fxl__rr_scale(tri->gpx[FXL__PA + FXL__AV], t);
    /* q's step, gq 2^(n - 32), where it is below 2^31 in magnitude (|gq|
     * has more than n leading zeros); else a run of one. The run ends
     * before q leaves [2^31, 2^32). */
    rr->dq = 0;
    if (left > 1 && gq != 0) {
        if (fxl__clz64_inline(gq < 0 ? (uint64_t)0 - (uint64_t)gq : (uint64_t)gq) > n) {
            rr->dq = fxl__rr_scale(gq, n - 32);
            left = fxl__rr_len(rr->q, rr->dq, left);
        } else {
            left = 1;
        }
    }
    rr->x = x;
    rr->left = left;
    rr->xe = xe;
}
#endif
