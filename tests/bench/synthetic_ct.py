#!/usr/bin/env python3
"""A synthetic abdominal CT for the large-scan benchmark (issue 20 §3): 512 x 512 x 400 int16
voxels of 0.7 x 0.7 x 1.0 mm written as an uncompressed NIfTI-1 file (200 MiB of voxels).
Air (-1000 HU) around an elliptic body of soft tissue (40 HU), a spine-like bone cylinder
(700 HU) and a liver-like ellipsoid (90 HU) whose voxels a threshold of 80:120 selects alone.
Standard library only. Usage: synthetic_ct.py OUT.nii"""
import math
import struct
import sys
from array import array

NX, NY, NZ = 512, 512, 400
SPACING = (0.7, 0.7, 1.0)


def header():
    h = bytearray(348)
    struct.pack_into("<i", h, 0, 348)
    struct.pack_into("<8h", h, 40, 3, NX, NY, NZ, 1, 1, 1, 1)
    struct.pack_into("<hh", h, 70, 4, 16)  # datatype int16, bitpix
    struct.pack_into("<8f", h, 76, 1.0, *SPACING, 1.0, 1.0, 1.0, 1.0)
    struct.pack_into("<f", h, 108, 352.0)  # vox_offset
    struct.pack_into("<ff", h, 112, 1.0, 0.0)  # scl_slope, scl_inter
    struct.pack_into("<B", h, 123, 2)  # xyzt_units: mm
    struct.pack_into("<hh", h, 252, 0, 1)  # qform_code 0, sform_code 1 (scanner)
    struct.pack_into("<4f", h, 280, SPACING[0], 0, 0, -0.5 * NX * SPACING[0])
    struct.pack_into("<4f", h, 296, 0, SPACING[1], 0, -0.5 * NY * SPACING[1])
    struct.pack_into("<4f", h, 312, 0, 0, SPACING[2], -0.5 * NZ * SPACING[2])
    h[344:348] = b"n+1\0"
    return bytes(h) + b"\0\0\0\0"


def span(centre, radius, d):
    """Index range [a, b) of x within `radius` of `centre` along a row at offset d (voxels)."""
    if abs(d) >= radius:
        return 0, 0
    half = math.sqrt(radius * radius - d * d)
    return max(0, int(math.ceil(centre - half))), min(NX, int(math.floor(centre + half)) + 1)


def main(path):
    with open(path, "wb") as out:
        out.write(header())
        air = array("h", [-1000]) * NX
        for z in range(NZ):
            for y in range(NY):
                row = array("h", air)
                # body: ellipse of semi-axes 220 x 160 voxels, centred
                dy = (y - 256) / 160.0
                if abs(dy) < 1.0:
                    half = 220.0 * math.sqrt(1.0 - dy * dy)
                    a, b = max(0, int(256 - half)), min(NX, int(256 + half) + 1)
                    row[a:b] = array("h", [40]) * (b - a)
                # spine: cylinder of radius 25 voxels along z behind the centre
                a, b = span(256, 25, y - 370)
                if b > a:
                    row[a:b] = array("h", [700]) * (b - a)
                # liver: ellipsoid of semi-axes 110, 80, 120 voxels (0.7, 0.7, 1 mm)
                q = ((y - 220) / 80.0) ** 2 + ((z - 200) / 120.0) ** 2
                if q < 1.0:
                    half = 110.0 * math.sqrt(1.0 - q)
                    a, b = max(0, int(180 - half)), min(NX, int(180 + half) + 1)
                    row[a:b] = array("h", [90]) * (b - a)
                row.tofile(out)


if __name__ == "__main__":
    main(sys.argv[1])
