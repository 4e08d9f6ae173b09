/* pfnoise-demo: pictures of the noise as 8-bit grey PNGs (written here,
 * uncompressed deflate, no dependency).
 *
 *   build/pfnoise-demo [dir]        (default build/noise)
 *
 *   noise2d.png           pf_noise2f, 16 x 16 lattice cells
 *   noise3d_fixed.png     pf_noise3_q15 on a slice, fixed point only
 *   fbm2d.png             pf_fbm2f, 8 octaves, footprint = pixel size
 *   plane_filtered.png    fbm on a ground plane in perspective, each pixel
 *                         passing its own footprint as filter_width
 *   plane_unfiltered.png  the same with filter_width = 0: the distance
 *                         aliases into moire and salt-and-pepper */
#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "pfcli.h"
#include "pfcli_out.h"
#include "pfnoise.h"

static const char usage[] =
    "usage: pfnoise-demo [DIR]\n"
    "Writes five 8-bit grey PNG pictures of libpfmath's noise to DIR (default\n"
    "build/noise; created when missing, its parent must exist): noise2d.png,\n"
    "noise3d_fixed.png, fbm2d.png, plane_unfiltered.png, plane_filtered.png.\n"
    "Each is written to a temporary file beside it and renamed into place (a\n"
    "symlink is written through); nothing else in DIR is touched.\n"
    "  -h, --help  this text (a directory whose name starts with '-': ./-name)\n"
    "Exit status: 0 ok, 1 write failure, 2 bad usage.\n";

/* one line on stderr, exit 2 */
static void die2(const char *msg, const char *arg)
{
    fprintf(stderr, "pfnoise-demo: %s", msg);
    for (const char *p = arg; *p; p++)
        fputc((unsigned char)*p < 0x20 || *p == 0x7f ? '?' : *p, stderr);
    fputc('\n', stderr);
    exit(2);
}

static uint32_t crc_table[256];

static void crc_init(void)
{
    for (uint32_t n = 0; n < 256; n++) {
        uint32_t c = n;
        for (int k = 0; k < 8; k++)
            c = c & 1 ? 0xedb88320u ^ (c >> 1) : c >> 1;
        crc_table[n] = c;
    }
}

static uint32_t crc(uint32_t c, const uint8_t *p, size_t n)
{
    c ^= 0xffffffffu;
    while (n--)
        c = crc_table[(c ^ *p++) & 0xff] ^ (c >> 8);
    return c ^ 0xffffffffu;
}

static void be32(uint8_t *p, uint32_t v)
{
    p[0] = (uint8_t)(v >> 24);
    p[1] = (uint8_t)(v >> 16);
    p[2] = (uint8_t)(v >> 8);
    p[3] = (uint8_t)v;
}

static void chunk(FILE *f, const char *type, const uint8_t *data, uint32_t n)
{
    uint8_t h[8];
    be32(h, n);
    memcpy(h + 4, type, 4);
    fwrite(h, 1, 8, f);
    if (n)
        fwrite(data, 1, n, f);
    uint32_t c = crc(crc(0, (const uint8_t *)type, 4), data, n);
    be32(h, c);
    fwrite(h, 1, 4, f);
}

/* Grey PNG: zlib stream of stored (uncompressed) deflate blocks. */
static int write_png(const char *path, const uint8_t *pix, int w, int h)
{
    size_t raw_n = (size_t)h * (size_t)(w + 1);
    uint8_t *raw = malloc(raw_n);
    for (int y = 0; y < h; y++) {
        raw[(size_t)y * (size_t)(w + 1)] = 0; /* filter: none */
        memcpy(raw + (size_t)y * (size_t)(w + 1) + 1, pix + (size_t)y * (size_t)w, (size_t)w);
    }
    size_t nblk = (raw_n + 65534) / 65535;
    size_t z_n = 2 + raw_n + 5 * nblk + 4;
    uint8_t *z = malloc(z_n), *q = z;
    *q++ = 0x78;
    *q++ = 0x01;
    uint32_t a = 1, b = 0;
    for (size_t off = 0; off < raw_n; off += 65535) {
        size_t len = raw_n - off < 65535 ? raw_n - off : 65535;
        *q++ = off + len == raw_n; /* BFINAL, BTYPE = 00 */
        *q++ = (uint8_t)len;
        *q++ = (uint8_t)(len >> 8);
        *q++ = (uint8_t)~len;
        *q++ = (uint8_t)(~len >> 8);
        memcpy(q, raw + off, len);
        q += len;
        for (size_t i = 0; i < len; i++) {
            a = (a + raw[off + i]) % 65521;
            b = (b + a) % 65521;
        }
    }
    be32(q, b << 16 | a);
    pfcli_out o;
    char err[600];
    if (pfcli_out_open(&o, path, err, sizeof err) != 0) {
        fprintf(stderr, "pfnoise-demo: %s\n", err);
        free(raw);
        free(z);
        return -1;
    }
    FILE *f = o.f;
    static const uint8_t sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    fwrite(sig, 1, 8, f);
    uint8_t ihdr[13];
    be32(ihdr, (uint32_t)w);
    be32(ihdr + 4, (uint32_t)h);
    ihdr[8] = 8; /* bit depth */
    ihdr[9] = 0; /* grey */
    ihdr[10] = ihdr[11] = ihdr[12] = 0;
    chunk(f, "IHDR", ihdr, 13);
    chunk(f, "IDAT", z, (uint32_t)z_n);
    chunk(f, "IEND", NULL, 0);
    free(raw);
    free(z);
    if (pfcli_out_commit(&o, err, sizeof err) != 0) {
        fprintf(stderr, "pfnoise-demo: %s\n", err);
        return -1;
    }
    printf("wrote %s (%dx%d)\n", path, w, h);
    return 0;
}

static uint8_t grey(float v) /* [-1, 1] -> [0, 255] */
{
    float g = (v * 0.5f + 0.5f) * 255.0f + 0.5f;
    return (uint8_t)(g < 0 ? 0 : g > 255 ? 255 : g);
}

int main(int argc, char **argv)
{
    if (argc > 1 && (!strcmp(argv[1], "-h") || !strcmp(argv[1], "--help"))) {
        fputs(usage, stdout);
        return 0;
    }
    if (argc > 1 && argv[1][0] == '-')
        die2("unknown option (see --help; a directory named so: ./NAME): ", argv[1]);
    if (argc > 2)
        die2("one directory at most; unexpected argument ", argv[2]);
    const char *dir = argc > 1 ? argv[1] : "build/noise";
    char path[PATH_MAX];
    if (!*dir)
        die2("empty directory name", "");
    if (strlen(dir) + sizeof "/plane_unfiltered.png" > sizeof path)
        die2("directory name too long: ", "");
    struct stat sb;
    if (stat(dir, &sb) == 0) {
        if (!S_ISDIR(sb.st_mode))
            die2("not a directory: ", dir);
    } else if (errno != ENOENT || mkdir(dir, 0777) != 0) {
        fprintf(stderr, "pfnoise-demo: ");
        for (const char *p = dir; *p; p++)
            fputc((unsigned char)*p < 0x20 || *p == 0x7f ? '?' : *p, stderr);
        fprintf(stderr, ": %s\n", strerror(errno));
        return 1;
    }
    crc_init();
    enum { W = 512, H = 512 };
    static uint8_t img[W * H];

    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++)
            img[y * W + x] = grey(pf_noise2f((float)x / 32.0f, (float)y / 32.0f));
    snprintf(path, sizeof path, "%s/noise2d.png", dir);
    if (write_png(path, img, W, H))
        return 1;

    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            int16_t v = pf_noise3_q15(x * 2048, y * 2048, 5 * 65536 + 21845); /* 1/32 unit */
            img[y * W + x] = (uint8_t)((v + 32768) >> 8);
        }
    snprintf(path, sizeof path, "%s/noise3d_fixed.png", dir);
    if (write_png(path, img, W, H))
        return 1;

    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++)
            img[y * W + x] =
                grey(1.6f * pf_fbm2f((float)x / 32.0f, (float)y / 32.0f, 8, 2.0f, 0.5f, 1.0f / 32));
    snprintf(path, sizeof path, "%s/fbm2d.png", dir);
    if (write_png(path, img, W, H))
        return 1;

    /* Ground plane z = -1 seen from the origin, looking along +y; pixel
     * (x, y) below the horizon hits (u, v) = (sx·d, d) with d = 1/sy.  The
     * footprint is the larger of the pixel's extents along u and v. */
    for (int pass = 0; pass < 2; pass++) {
        for (int y = 0; y < H / 2; y++)
            for (int x = 0; x < W; x++) {
                float sy = ((float)y + 0.5f) / (float)(H / 2) * 0.5f + 1e-3f; /* below horizon */
                float sx = ((float)x + 0.5f - W / 2.0f) / (float)(H / 2) * 0.5f;
                float d = 1.0f / sy, u = 8.0f * sx * d, v = 8.0f * d;
                float px = 0.5f / (float)(H / 2);
                float fw = pass ? 8.0f * fmaxf(px * d, px * d * d) : 0.0f;
                img[y * W + x] = grey(1.6f * pf_fbm2f(u, v, 10, 2.0f, 0.6f, fw));
            }
        snprintf(path, sizeof path, "%s/plane_%s.png", dir, pass ? "filtered" : "unfiltered");
        if (write_png(path, img + 0, W, H / 2))
            return 1;
    }
    return 0;
}
