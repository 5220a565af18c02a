#!/usr/bin/python3
"""Header facts of the real image files that Debian packages ship, read by libraries no one in
Viscera wrote (pydicom, nibabel) or by parsing the text header (INRIMAGE). The volume reader
tests compare read_volume() against this JSON; nothing here uses Viscera.

Usage: volume_headers.py INR_FOLDER  → JSON list on stdout, one entry per file:
  path, format, and either
    dims [x, y, z], spacing_mm [x, y, z] (null when the file gives none),
    corners_lps_mm (world positions of the 8 corner voxel centres, LPS; null when unknown)
  or error: a word the reader's message must contain.
"""
import glob
import gzip
import itertools
import json
import os
import sys
import warnings

import numpy as np

warnings.simplefilter("ignore")
entries = []


def corners(affine, shape):
    """The 8 corner voxel centres of a voxel→RAS affine (mm), converted to LPS."""
    points = []
    for ijk in itertools.product(*[(0, n - 1) for n in shape[:3]]):
        x, y, z, _ = affine @ np.array([*ijk, 1.0])
        points.append([-float(x), -float(y), float(z)])
    return points


# DICOM: pydicom's and nibabel's test files.
import pydicom

dicom_dirs = ["/usr/lib/python3/dist-packages/pydicom/data/test_files",
              "/usr/lib/python3/dist-packages/nibabel/nicom/tests/data",
              "/usr/lib/python3/dist-packages/nibabel/tests/data"]
for folder in dicom_dirs:
    for path in sorted(glob.glob(os.path.join(folder, "*.dcm"))):
        try:
            d = pydicom.dcmread(path, force=True)
        except Exception:
            continue
        if "Rows" not in d or "Columns" not in d:
            continue  # not an image: reports, plans, structure sets, waveforms
        entry = {"path": path, "format": "DICOM"}
        text = str(d.get("NumberOfFrames", 1) or 1)
        digits = "".join(itertools.takewhile(str.isdigit, text.strip()))  # badVR.dcm says "1A"
        frames = int(digits or 1)
        if "PixelData" not in d:
            entry["error"] = "GDCM cannot read the image"
            entries.append(entry)
            continue
        ts = d.file_meta.get("TransferSyntaxUID") if hasattr(d, "file_meta") else None
        compressed = ts is not None and ts.is_compressed
        samples = int(d.get("SamplesPerPixel", 1))
        if str(d.get("PhotometricInterpretation", "")).endswith(("_422", "_420")):
            samples = 2  # chroma subsampled: two samples a pixel on average
        needed = d.Rows * d.Columns * frames * samples * int(d.BitsAllocated) // 8
        if not compressed and int(d.BitsAllocated) >= 8 and len(d.PixelData) < needed:
            entry["error"] = "truncated"
            entries.append(entry)
            continue
        spacing = d.get("PixelSpacing")
        if spacing is None and "SharedFunctionalGroupsSequence" in d:
            groups = d.SharedFunctionalGroupsSequence[0]
            if "PixelMeasuresSequence" in groups:
                spacing = groups.PixelMeasuresSequence[0].get("PixelSpacing")
        if spacing is None:
            spacing = d.get("ImagerPixelSpacing")
        entry["dims"] = [int(d.Columns), int(d.Rows), frames]
        # Pixel Spacing is (between rows, between columns): x steps by the second value.
        entry["spacing_mm"] = [float(spacing[1]), float(spacing[0]), None] if spacing else None
        entry["transfer_syntax"] = str(getattr(ts, "name", ts))
        entry["photometric"] = str(d.get("PhotometricInterpretation", ""))
        if not compressed and samples == 1 and entry["photometric"].startswith("MONOCHROME") and frames == 1:
            try:
                values = d.pixel_array.astype(float) * float(d.get("RescaleSlope", 1) or 1) + float(
                    d.get("RescaleIntercept", 0) or 0)
                entry["value_range"] = [float(values.min()), float(values.max())]
            except Exception:
                pass  # pydicom has no handler for it: no values to compare
        entries.append(entry)

# DICOM series: pydicom's folders of single-slice files, grouped by Series Instance UID; the
# largest series, its slices ordered along the normal of their planes.
series_root = "/usr/lib/python3/dist-packages/pydicom/data/test_files/dicomdirtests"
for folder in ["98892001"]:
    by_uid = {}
    for path in sorted(glob.glob(os.path.join(series_root, folder, "**", "*"), recursive=True)):
        if os.path.isdir(path):
            continue
        d = pydicom.dcmread(path, force=True)
        if "Rows" in d and "PixelData" in d:
            by_uid.setdefault(str(d.SeriesInstanceUID), []).append(d)
    largest = max(by_uid.values(), key=len)
    row, col = np.array(largest[0].ImageOrientationPatient[:3], float), np.array(largest[0].ImageOrientationPatient[3:], float)
    normal = np.cross(row, col)
    positions = sorted(float(np.dot(np.array(d.ImagePositionPatient, float), normal)) for d in largest)
    entries.append({"path": os.path.join(series_root, folder), "format": "DICOM",
                    "dims": [int(largest[0].Columns), int(largest[0].Rows), len(largest)],
                    "spacing_mm": [float(largest[0].PixelSpacing[1]), float(largest[0].PixelSpacing[0]),
                                   (positions[-1] - positions[0]) / (len(positions) - 1)],
                    "other_series": len(by_uid) - 1})

# NIfTI, Analyze and MINC: nibabel's test data.
import nibabel

nib_dir = "/usr/lib/python3/dist-packages/nibabel/tests/data"
for pattern in ["*.nii", "*.nii.gz", "*.hdr", "*.mnc"]:
    for path in sorted(glob.glob(os.path.join(nib_dir, pattern))):
        fmt = "MINC" if path.endswith(".mnc") else "NIfTI"
        entry = {"path": path, "format": fmt}
        with open(path, "rb") as f:
            magic = f.read(4)
        if magic[1:4] == b"HDF":
            entry["error"] = "MINC 2 (HDF5)"
            entries.append(entry)
            continue
        if path.endswith(".hdr") and not os.path.exists(path[:-4] + ".img"):
            entry["error"] = "missing"
            entries.append(entry)
            continue
        try:
            image = nibabel.load(path)
        except Exception as e:  # nibabel cannot read it either: record why
            entry["nibabel_error"] = str(e)
            entries.append(entry)
            continue
        if fmt == "NIfTI" and hasattr(image, "affine") and not np.isfinite(image.get_fdata()).all():
            entry["error"] = "is NaN or infinite"
            entries.append(entry)
            continue
        if not hasattr(image, "affine"):
            continue  # CIFTI (row_major.dconn.nii): brain-ordinate matrices, not image volumes
        full_shape = [int(n) for n in image.shape]
        if fmt == "MINC" and len(full_shape) == 4:
            full_shape = full_shape[1:]  # MINC puts time first; the affine is spatial only
        shape = full_shape[:3] + [1] * (3 - len(image.shape[:3]))
        affine = np.array(image.affine, dtype=float)
        scale = 1.0
        if fmt == "NIfTI":
            unit = image.header.get_xyzt_units()[0]
            scale = {"meter": 1000.0, "mm": 1.0, "micron": 0.001}.get(unit, 1.0)
        affine[:3, :] *= scale
        entry["dims"] = shape
        entry["spacing_mm"] = [float(np.linalg.norm(affine[:3, c])) for c in range(3)]
        entry["corners_lps_mm"] = corners(affine, shape)
        entries.append(entry)

# INRIMAGE: CGAL's image data (extracted by the test into the folder given).
if len(sys.argv) > 1:
    for path in sorted(glob.glob(os.path.join(sys.argv[1], "*.inr*"))):
        opener = gzip.open if path.endswith(".gz") else open
        with opener(path, "rb") as f:
            data = f.read()
        end = data.find(b"##}")
        header_bytes = (end // 256 + 1) * 256
        fields = dict(line.split("=", 1) for line in data[:end].decode().split("\n") if "=" in line)
        dims = [int(fields["XDIM"]), int(fields["YDIM"]), int(fields.get("ZDIM", 1))]
        bits = int(fields["PIXSIZE"].split()[0])
        entry = {"path": path, "format": "INRIMAGE"}
        if len(data) - header_bytes < dims[0] * dims[1] * dims[2] * int(fields.get("VDIM", 1)) * bits // 8:
            entry["error"] = "truncated"
        else:
            entry["dims"] = dims
            entry["spacing_mm"] = [float(fields.get(k, 1)) for k in ("VX", "VY", "VZ")]
        entries.append(entry)

json.dump(entries, sys.stdout, indent=1)
