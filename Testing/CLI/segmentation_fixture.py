# SPDX-License-Identifier: GPL-2.0-or-later
"""Writes the label files labelmesher reads names and colours from, as their
programs write them, for tests without those programs (plain Python 3 + numpy):

    write_seg_nrrd(path, layers, segments, ...)   3D Slicer segmentation (.seg.nrrd)
    write_itksnap_labels(path, entries)           ITK-SNAP label description
    write_slicer_ctbl(path, entries)              3D Slicer colour table (.ctbl)

Arrays are indexed [z, y, x]; colour-table entries are (label, name, (r, g, b))
with r, g, b in 0..255."""

import gzip

import numpy as np

_SEGMENTATION_CONVERSION = (
    "Collapse labelmaps|1|Merge the labelmaps into as few shared labelmaps as possible "
    "1 = created labelmaps will be shared if possible without overwriting each other.&"
    "Compute surface normals|1|Compute surface normals. 1 (default) = surface normals are computed. "
    "0 = surface normals are not computed (slightly faster but produces less smooth surface display).&"
    "Crop to reference image geometry|0|Crop the model to the extent of reference geometry. "
    "0 (default) = created labelmap will contain the entire model. "
    "1 = created labelmap extent will be within reference image extent.&"
    "Decimation factor|0.0|Desired reduction in the total number of polygons. Range: 0.0 (no decimation) "
    "to 1.0 (as much simplification as possible).&"
    "Joint smoothing|0|Perform joint smoothing.&"
    "Oversampling factor|1|Determines the oversampling of the reference image geometry.&"
    "Reference image geometry|{geometry}|Image geometry description string determining the geometry "
    "of the labelmap that is created in course of conversion.&"
    "Smoothing factor|0.5|Smoothing factor.&"
    "Threshold fraction|0.5|Determines the threshold that the closed surface is created at as a "
    "fractional value between 0 and 1.&"
)


def _number(x):
    """A float as Slicer (Teem) prints it in the header: %.17g."""
    return format(float(x), ".17g")


def _extent(mask):
    """Slicer's Segment<i>_Extent: minI maxI minJ maxJ minK maxK of the mask, or empty."""
    if not mask.any():
        return "0 -1 0 -1 0 -1"
    k, j, i = np.nonzero(mask)
    return f"{i.min()} {i.max()} {j.min()} {j.max()} {k.min()} {k.max()}"


def write_seg_nrrd(path, layers, segments, spacing=(1, 1, 1), origin=(0, 0, 0), encoding="gzip",
                   overrides=None):
    """3D Slicer segmentation: one layer gives a 3D NRRD, several a 4D one whose
    first axis (`list`) runs over the layers.

    layers:    list of 3D integer arrays [z, y, x] of one shape, one per layer
    segments:  list of dicts {name, color: (r, g, b) in 0..1, label, layer}, in
               file order (Segment0, Segment1, ...); [] writes no segment keys
    encoding:  "gzip" (as Slicer) or "raw"
    overrides: {key: value} replacing or adding `key:=value` fields (value
               None removes the field), to write the broken files tests need
    """
    layers = [np.asarray(layer) for layer in layers]
    if not layers or any(layer.ndim != 3 or layer.shape != layers[0].shape for layer in layers):
        raise ValueError("layers: one or more 3D arrays [z, y, x] of one shape")
    low = min(int(layer.min()) for layer in layers)
    high = max(int(layer.max()) for layer in layers)
    if 0 <= low and high <= 255:
        nrrd_type, dtype = "unsigned char", np.uint8
    elif -32768 <= low and high <= 32767:
        nrrd_type, dtype = "short", np.dtype("<i2")
    else:
        raise ValueError("labels beyond 16 bits: Slicer stores segmentations as unsigned char or short")
    nz, ny, nx = layers[0].shape
    sx, sy, sz = (float(s) for s in spacing)
    ox, oy, oz = (float(o) for o in origin)
    directions = f"({_number(sx)},0,0) (0,{_number(sy)},0) (0,0,{_number(sz)})"
    if len(layers) == 1:
        data = layers[0].astype(dtype)
        dimension, sizes, kinds = 3, f"{nx} {ny} {nz}", "domain domain domain"
    else:
        data = np.stack([layer.astype(dtype) for layer in layers], axis=-1)  # layer fastest
        dimension, sizes, kinds = 4, f"{len(layers)} {nx} {ny} {nz}", "list domain domain domain"
        directions = "none " + directions

    header = [
        "NRRD0004",
        "# Complete NRRD file format specification at:",
        "# http://teem.sourceforge.net/nrrd/format.html",
        f"type: {nrrd_type}",
        f"dimension: {dimension}",
        "space: left-posterior-superior",
        f"sizes: {sizes}",
        f"space directions: {directions}",
        f"kinds: {kinds}",
    ]
    if np.dtype(dtype).itemsize > 1:
        header.append("endian: little")
    header += [f"encoding: {encoding}", f"space origin: ({_number(ox)},{_number(oy)},{_number(oz)})"]

    # Slicer's reference geometry: image-to-RAS matrix (LPS flipped), then the extent.
    matrix = [-sx, 0, 0, -ox + 0.0, 0, -sy, 0, -oy + 0.0, 0, 0, sz, oz, 0, 0, 0, 1]
    geometry = "".join(_number(v) + ";" for v in matrix) + f"0;{nx - 1};0;{ny - 1};0;{nz - 1};"
    fields = {
        "Segmentation_ContainedRepresentationNames": "Binary labelmap|",
        "Segmentation_ConversionParameters": _SEGMENTATION_CONVERSION.format(geometry=geometry),
        "Segmentation_MasterRepresentation": "Binary labelmap",
        "Segmentation_ReferenceImageExtentOffset": "0 0 0",
        "Segmentation_SourceRepresentation": "Binary labelmap",
    }
    for i, segment in enumerate(segments):
        layer = int(segment.get("layer", 0))
        label = int(segment["label"])
        mask = layers[layer] == label if 0 <= layer < len(layers) else np.zeros((1, 1, 1), bool)
        prefix = f"Segment{i}_"
        fields.update({
            prefix + "Color": " ".join(f"{float(c):g}" for c in segment["color"]),
            prefix + "ColorAutoGenerated": "0",
            prefix + "Extent": _extent(mask),
            prefix + "ID": f"Segment_{i + 1}",
            prefix + "LabelValue": str(label),
            prefix + "Layer": str(layer),
            prefix + "Name": segment["name"],
            prefix + "NameAutoGenerated": "0",
            prefix + "Tags": "|",
        })
    for key, value in (overrides or {}).items():
        if value is None:
            fields.pop(key, None)
        else:
            fields[key] = str(value)
    header += [f"{key}:={fields[key]}" for key in sorted(fields)]  # Slicer writes them sorted

    payload = np.ascontiguousarray(data).tobytes()
    if encoding == "gzip":
        payload = gzip.compress(payload, mtime=0)  # the same bytes on every run
    elif encoding != "raw":
        raise ValueError("encoding: gzip or raw")
    with open(path, "wb") as f:
        f.write(("\n".join(header) + "\n\n").encode("utf-8") + payload)
    return path


def write_itksnap_labels(path, entries, clear_label=True):
    """ITK-SNAP label description file; label 0 "Clear Label" first, as ITK-SNAP
    writes it, unless `entries` names label 0 or clear_label is False."""
    lines = [
        "################################################",
        "# ITK-SnAP Label Description File",
        "# File format: ",
        "# IDX   -R-  -G-  -B-  -A--  VIS MSH  LABEL",
        "# Fields: ",
        "#    IDX:   Zero-based index ",
        "#    -R-:   Red color component (0..255)",
        "#    -G-:   Green color component (0..255)",
        "#    -B-:   Blue color component (0..255)",
        "#    -A-:   Label transparency (0.00 .. 1.00)",
        "#    VIS:   Label visibility (0 or 1)",
        "#    IDX:   Label mesh visibility (0 or 1)",
        "#  LABEL:   Label description ",
        "################################################",
    ]
    entries = list(entries)
    if clear_label and all(label != 0 for label, _, _ in entries):
        lines.append(f'{0:5d} {0:5d} {0:4d} {0:4d} {0:8g} {0:2d} {0:2d}    "Clear Label"')
    for label, name, (r, g, b) in entries:
        lines.append(f'{label:5d} {r:5d} {g:4d} {b:4d} {1:8g} {1:2d} {1:2d}    "{name}"')
    with open(path, "w", encoding="utf-8") as f:
        f.write("\n".join(lines) + "\n")
    return path


def write_slicer_ctbl(path, entries):
    """3D Slicer colour table; Slicer writes names with '_' for spaces, alpha 0
    for label 0 (background) and 255 for the others."""
    lines = [f"# Color table file {path}", f"# {len(entries)} values"]
    for label, name, (r, g, b) in entries:
        lines.append(f"{label} {name.replace(' ', '_')} {r} {g} {b} {0 if label == 0 else 255}")
    with open(path, "w", encoding="utf-8") as f:
        f.write("\n".join(lines) + "\n")
    return path
