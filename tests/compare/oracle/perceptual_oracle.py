#!/usr/bin/python3
"""Independent values for tests/compare/perceptual.cpp.

SSIM: scikit-image 0.19.3 (Debian 12 python3-skimage), structural_similarity with
gaussian_weights=True, sigma=1.5, use_sample_covariance=False, data_range=1 (Wang et al. 2004).
LDR-FLIP: a direct numpy transcription of Andersson et al., HPG 2020 (full 2-D kernels, edge
padding), written separately from compare/src/flip.cpp (which uses separable passes).

Run: /usr/bin/python3 tests/compare/oracle/perceptual_oracle.py
"""
import numpy as np
from skimage.metrics import structural_similarity

W, H = 48, 40


def pattern(kind):
    y, x = np.mgrid[0:H, 0:W].astype(np.float64)
    img = np.zeros((H, W, 3), np.float64)
    for c in range(3):
        ref = 0.5 + 0.35 * np.sin(0.21 * x + 0.9 * c) * np.cos(0.17 * y - 0.4 * c)
        if kind == 'ref':
            img[:, :, c] = ref
        else:
            img[:, :, c] = ref + 0.12 * np.sin(0.37 * x + 0.23 * y + 1.3 * c)
    if kind == 'test':
        img[10:18, 30:38, :] = 0.95
    return img.astype(np.float32)


def luminance(img):
    return (0.2126 * img[:, :, 0].astype(np.float64) + 0.7152 * img[:, :, 1] + 0.0722 * img[:, :, 2]).astype(np.float32)


# ---- FLIP -------------------------------------------------------------------------------
PPD = 3840 * np.pi / 180
REF_WHITE = np.array([0.950428545, 1.0, 1.088900371])


def srgb_to_lin(v):
    return np.where(v <= 0.04045, v / 12.92, ((v + 0.055) / 1.055) ** 2.4)


M_XYZ = np.array([[10135552 / 24577794, 8788810 / 24577794, 4435075 / 24577794],
                  [2613072 / 12288897, 8788810 / 12288897, 887015 / 12288897],
                  [1425312 / 73733382, 8788810 / 73733382, 70074185 / 73733382]])
M_RGB = np.array([[3.241003275, -1.537398934, -0.498615861],
                  [-0.969224334, 1.875930071, 0.041554224],
                  [0.055639423, -0.204011202, 1.057148933]])


def lin_to_ycxcz(rgb):
    xyz = rgb @ M_XYZ.T / REF_WHITE
    return np.stack([116 * xyz[..., 1] - 16, 500 * (xyz[..., 0] - xyz[..., 1]), 200 * (xyz[..., 1] - xyz[..., 2])], -1)


def ycxcz_to_lin(o):
    y = (o[..., 0] + 16) / 116
    xyz = np.stack([y + o[..., 1] / 500, y, y - o[..., 2] / 200], -1) * REF_WHITE
    return xyz @ M_RGB.T


def lin_to_hunt_lab(rgb):
    xyz = rgb @ M_XYZ.T / REF_WHITE
    d = 6 / 29
    f = np.where(xyz > d ** 3, np.cbrt(xyz), xyz / (3 * d * d) + 4 / 29)
    L = 116 * f[..., 1] - 16
    a = 500 * (f[..., 0] - f[..., 1])
    b = 200 * (f[..., 1] - f[..., 2])
    return np.stack([L, 0.01 * L * a, 0.01 * L * b], -1)


def hyab(p, q):
    d = p - q
    return np.abs(d[..., 0]) + np.sqrt(d[..., 1] ** 2 + d[..., 2] ** 2)


def conv2d_edge(img, k):
    r = k.shape[0] // 2
    p = np.pad(img, r, mode='edge')
    out = np.zeros_like(img)
    for dy in range(-r, r + 1):
        for dx in range(-r, r + 1):
            out += k[dy + r, dx + r] * p[r + dy:r + dy + img.shape[0], r + dx:r + dx + img.shape[1]]
    return out


def csf_kernel(a1, b1, a2, b2):
    r = int(np.ceil(3 * np.sqrt(0.04 / (2 * np.pi ** 2)) * PPD))
    yy, xx = np.mgrid[-r:r + 1, -r:r + 1]
    z = (xx / PPD) ** 2 + (yy / PPD) ** 2
    g = a1 * np.sqrt(np.pi / b1) * np.exp(-np.pi ** 2 * z / b1) + a2 * np.sqrt(np.pi / b2) * np.exp(-np.pi ** 2 * z / b2)
    return g / g.sum()


def feature_kernel(point):
    sd = 0.5 * 0.082 * PPD
    r = int(np.ceil(3 * sd))
    yy, xx = np.mgrid[-r:r + 1, -r:r + 1]
    g = np.exp(-(xx ** 2 + yy ** 2) / (2 * sd * sd))
    k = (xx ** 2 / (sd * sd) - 1) * g if point else -xx * g
    return np.where(k < 0, k / -k[k < 0].sum(), k / k[k > 0].sum())


def flip(ref_srgb, test_srgb):
    ref = lin_to_ycxcz(srgb_to_lin(np.clip(ref_srgb.astype(np.float64), 0, 1)))
    tst = lin_to_ycxcz(srgb_to_lin(np.clip(test_srgb.astype(np.float64), 0, 1)))
    params = [(1, 0.0047, 0, 1e-5), (1, 0.0053, 0, 1e-5), (34.1, 0.04, 13.5, 0.025)]
    rf = np.stack([conv2d_edge(ref[..., c], csf_kernel(*params[c])) for c in range(3)], -1)
    tf = np.stack([conv2d_edge(tst[..., c], csf_kernel(*params[c])) for c in range(3)], -1)
    rl = lin_to_hunt_lab(np.clip(ycxcz_to_lin(rf), 0, 1))
    tl = lin_to_hunt_lab(np.clip(ycxcz_to_lin(tf), 0, 1))
    qc, qf, pc, pt = 0.7, 0.5, 0.4, 0.95
    dc = hyab(rl, tl) ** qc
    cmax = hyab(lin_to_hunt_lab(np.array([0.0, 1, 0])), lin_to_hunt_lab(np.array([0.0, 0, 1]))) ** qc
    dc = np.where(dc < pc * cmax, pt / (pc * cmax) * dc, pt + (dc - pc * cmax) / (cmax - pc * cmax) * (1 - pt))
    ry, ty = (ref[..., 0] + 16) / 116, (tst[..., 0] + 16) / 116
    feats = []
    for point in (False, True):
        k = feature_kernel(point)
        mag = lambda y: np.hypot(conv2d_edge(y, k), conv2d_edge(y, k.T))
        feats.append(np.abs(mag(ry) - mag(ty)))
    df = (np.maximum(feats[0], feats[1]) / np.sqrt(2)) ** qf
    e = dc ** (1 - df)
    return e.mean(), e.max(), e


if __name__ == '__main__':
    a, b = pattern('ref'), pattern('test')
    s = structural_similarity(luminance(a).astype(np.float64), luminance(b).astype(np.float64), gaussian_weights=True,
                              sigma=1.5, use_sample_covariance=False, data_range=1.0)
    print('ssim(ref, test) = %.10f' % s)
    # constant images: SSIM = (2 m1 m2 + C1) / (m1^2 + m2^2 + C1)
    c1 = np.full((16, 16), 0.5)
    c2 = np.full((16, 16), 0.25)
    print('ssim(0.5, 0.25) = %.10f' % structural_similarity(c1, c2, gaussian_weights=True, sigma=1.5,
                                                             use_sample_covariance=False, data_range=1.0))
    mean, mx, e = flip(a, b)
    print('flip(ref, test): mean = %.10f, max = %.10f, at (x=%d, y=%d) = %.10f' %
          (mean, mx, 5, 7, e[7, 5]))
    black = np.zeros((16, 16, 3), np.float32)
    white = np.ones((16, 16, 3), np.float32)
    mean, mx, _ = flip(black, white)
    print('flip(black, white): mean = %.10f, max = %.10f' % (mean, mx))
    grey = np.full((16, 16, 3), 0.5, np.float32)
    mean, mx, _ = flip(black, grey)
    print('flip(black, grey 0.5): mean = %.10f, max = %.10f' % (mean, mx))
