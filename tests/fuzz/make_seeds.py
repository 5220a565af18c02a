#!/usr/bin/env python3
"""Writes the small hand-made seed files of the fuzz corpus (tests/fuzz/seeds/<target>/) for
the formats no Debian package ships an example of: one tetrahedron (4 nodes, 4 outward faces) in
every mesh format, a 2x2x2 volume in every raw volume format, a haptic pose packet and input
options. gmsh's own files, DICOM, NIfTI and MINC seeds come from Debian packages (seeds.txt);
packages and traces are written by Viscera itself (`./dev.sh fuzz` adds them).
Run from the repository root: python3 tests/fuzz/make_seeds.py"""
import base64, json, os, struct, zlib

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "seeds")
NODES = [(0.0, 0.0, 0.0), (0.01, 0.0, 0.0), (0.0, 0.01, 0.0), (0.0, 0.0, 0.01)]
FACES = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]  # outward


def put(target, name, data):
    os.makedirs(os.path.join(ROOT, target), exist_ok=True)
    with open(os.path.join(ROOT, target, name), "wb") as f:
        f.write(data.encode() if isinstance(data, str) else data)


def normal(face):
    a, b, c = (NODES[i] for i in face)
    u = [b[k] - a[k] for k in range(3)]
    v = [c[k] - a[k] for k in range(3)]
    n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
    length = sum(x * x for x in n) ** 0.5
    return [x / length for x in n]


def meshes():
    put("mesh_off", "tetra.off", "OFF\n4 4 0\n" + "".join("%g %g %g\n" % p for p in NODES)
        + "".join("3 %d %d %d\n" % f for f in FACES))
    put("mesh_obj", "tetra.obj", "".join("v %g %g %g\n" % p for p in NODES)
        + "".join("f %d %d %d\n" % tuple(i + 1 for i in f) for f in FACES))
    ascii_stl = "solid tetra\n"
    binary_stl = b"tetra".ljust(80, b" ") + struct.pack("<I", len(FACES))
    for f in FACES:
        n = normal(f)
        ascii_stl += " facet normal %g %g %g\n  outer loop\n" % tuple(n)
        ascii_stl += "".join("   vertex %g %g %g\n" % NODES[i] for i in f)
        ascii_stl += "  endloop\n endfacet\n"
        binary_stl += struct.pack("<3f", *n) + b"".join(struct.pack("<3f", *NODES[i]) for i in f)
        binary_stl += b"\0\0"
    put("mesh_stl", "tetra_ascii.stl", ascii_stl + "endsolid tetra\n")
    put("mesh_stl", "tetra_binary.stl", binary_stl)
    put("mesh_ply", "tetra.ply", "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\n"
        "property float y\nproperty float z\nelement face 4\nproperty list uchar int vertex_indices\n"
        "end_header\n" + "".join("%g %g %g\n" % p for p in NODES)
        + "".join("3 %d %d %d\n" % f for f in FACES))
    positions = b"".join(struct.pack("<3f", *p) for p in NODES)
    indices = b"".join(struct.pack("<3H", *f) for f in FACES)
    buffer = positions + indices
    gltf = {
        "asset": {"version": "2.0"},
        "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
        "buffers": [{"byteLength": len(buffer)}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": len(positions)},
                        {"buffer": 0, "byteOffset": len(positions), "byteLength": len(indices)}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
                       "min": [0, 0, 0], "max": [0.01, 0.01, 0.01]},
                      {"bufferView": 1, "componentType": 5123, "count": 12, "type": "SCALAR"}],
    }
    embedded = json.loads(json.dumps(gltf))
    embedded["buffers"][0]["uri"] = ("data:application/octet-stream;base64,"
                                     + base64.b64encode(buffer).decode())
    put("mesh_gltf", "tetra.gltf", json.dumps(embedded, indent=1))
    text = json.dumps(gltf).encode()
    text += b" " * (-len(text) % 4)
    body = buffer + b"\0" * (-len(buffer) % 4)
    glb = struct.pack("<4sII", b"glTF", 2, 12 + 8 + len(text) + 8 + len(body))
    glb += struct.pack("<I4s", len(text), b"JSON") + text + struct.pack("<I4s", len(body), b"BIN\0") + body
    put("mesh_glb", "tetra.glb", glb)
    points = " ".join("%g %g %g" % p for p in NODES)
    put("mesh_vtp", "tetra.vtp",
        '<?xml version="1.0"?>\n<VTKFile type="PolyData" version="0.1" byte_order="LittleEndian">\n'
        '<PolyData><Piece NumberOfPoints="4" NumberOfPolys="4">\n'
        '<Points><DataArray type="Float64" NumberOfComponents="3" format="ascii">%s</DataArray></Points>\n'
        '<Polys><DataArray type="Int64" Name="connectivity" format="ascii">%s</DataArray>\n'
        '<DataArray type="Int64" Name="offsets" format="ascii">3 6 9 12</DataArray></Polys>\n'
        '</Piece></PolyData></VTKFile>\n' % (points, " ".join("%d %d %d" % f for f in FACES)))
    put("mesh_vtk", "tetra.vtk", "# vtk DataFile Version 4.2\ntetra\nASCII\nDATASET POLYDATA\n"
        "POINTS 4 double\n" + "".join("%g %g %g\n" % p for p in NODES)
        + "POLYGONS 4 16\n" + "".join("3 %d %d %d\n" % f for f in FACES))
    put("tet_mesh_vtu", "tetra.vtu",
        '<?xml version="1.0"?>\n<VTKFile type="UnstructuredGrid" version="0.1" byte_order="LittleEndian">\n'
        '<UnstructuredGrid><Piece NumberOfPoints="4" NumberOfCells="1">\n'
        '<Points><DataArray type="Float64" NumberOfComponents="3" format="ascii">%s</DataArray></Points>\n'
        '<Cells><DataArray type="Int64" Name="connectivity" format="ascii">0 1 2 3</DataArray>\n'
        '<DataArray type="Int64" Name="offsets" format="ascii">4</DataArray>\n'
        '<DataArray type="UInt8" Name="types" format="ascii">10</DataArray></Cells>\n'
        '<CellData><DataArray type="Int32" Name="tet_label" format="ascii">1</DataArray></CellData>\n'
        '</Piece></UnstructuredGrid></VTKFile>\n' % points)


def volumes():
    voxels = bytes([0, 10, 20, 30, 40, 50, 60, 70])
    put("volume_nrrd", "cube.nrrd", b"NRRD0004\ntype: uint8\ndimension: 3\nsizes: 2 2 2\n"
        b"space: left-posterior-superior\nspace directions: (1,0,0) (0,1,0) (0,0,2)\n"
        b"space origin: (0,0,0)\nencoding: raw\n\n" + voxels)
    put("volume_nrrd", "cube_gzip.nrrd", b"NRRD0004\ntype: short\ndimension: 3\nsizes: 2 2 2\n"
        b"spacings: 0.5 0.5 1\nendian: little\nencoding: gzip\n\n"
        + zlib.compress(struct.pack("<8h", *range(-4, 4))))
    put("volume_metaimage", "cube.mha", b"ObjectType = Image\nNDims = 3\nBinaryData = True\n"
        b"BinaryDataByteOrderMSB = False\nTransformMatrix = 1 0 0 0 1 0 0 0 1\nOffset = 0 0 0\n"
        b"ElementSpacing = 1 1 2\nDimSize = 2 2 2\nElementType = MET_UCHAR\n"
        b"ElementDataFile = LOCAL\n" + voxels)
    put("volume_vti", "cube.vti",
        '<?xml version="1.0"?>\n<VTKFile type="ImageData" version="0.1" byte_order="LittleEndian">\n'
        '<ImageData WholeExtent="0 1 0 1 0 1" Origin="0 0 0" Spacing="0.001 0.001 0.002">\n'
        '<Piece Extent="0 1 0 1 0 1"><PointData Scalars="labels">\n'
        '<DataArray type="UInt8" Name="labels" format="ascii">0 10 20 30 40 50 60 70</DataArray>\n'
        '</PointData></Piece></ImageData></VTKFile>\n')
    header = ("#INRIMAGE-4#{\nXDIM=2\nYDIM=2\nZDIM=2\nVDIM=1\nTYPE=unsigned fixed\nPIXSIZE=8 bits\n"
              "CPU=decm\nVX=1\nVY=1\nVZ=2\n")
    put("volume_inr", "cube.inr", (header + "\n" * (252 - len(header)) + "##}\n").encode() + voxels)


def device():
    body = struct.pack("<4sHHIIQ3d4dIff", b"VSCD", 1, 1, 7, 0, 123456789, 0.01, -0.02, 0.15,
                       1.0, 0.0, 0.0, 0.0, 1, 0.5, 0.25)
    put("pose_packet", "pose.bin", body + struct.pack("<I", zlib.crc32(body) & 0xFFFFFFFF))
    for n, text in enumerate(["keyboard", "gamepad", "udp:5000", "script:waypoints.json",
                              "trace:session.json"]):
        put("input_option", "option%d.txt" % n, text)


if __name__ == "__main__":
    meshes()
    volumes()
    device()
