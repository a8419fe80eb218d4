// mesh/gltf_io: glTF 2.0 through tinygltf behind a C interface (see
// gltf_io.h). The document is parsed with tinygltf (Debian's shared
// libtinygltf: its JSON and image code are not compiled here); this file
// only walks meshes, primitives and accessors, checking every byte range
// before it reads it, and appends the rewritten vertex data.
#include <tiny_gltf.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <new>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "mesh/gltf_io.h"

extern "C" {
#include "base/atomic_file.h"
}

namespace
{

int uv_set_index = 0;

// A failure on the way: the status and the message (without the name).
struct fail {
    scaf_status status;
    std::string message;
};

[[noreturn]] void refuse(scaf_status st, const std::string &m) { throw fail{st, m}; }

std::string where(int mesh, int prim)
{
    return "mesh " + std::to_string(mesh) + " primitive " + std::to_string(prim);
}

// ---- images: kept as they are (never decoded, never re-encoded) ----

// tinygltf hands every image's bytes to the loader. Those of data-URI
// images are kept (they are written back as a data URI); images in a
// buffer view or an external file keep their reference instead.
bool keep_image(tinygltf::Image *image, const int, std::string *, std::string *, int, int,
                const unsigned char *bytes, int size, void *)
{
    if (image->bufferView < 0 && image->uri.empty() && size > 0)
        image->image.assign(bytes, bytes + size);
    return true;
}

std::string base64(const std::vector<unsigned char> &in)
{
    static const char digits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((in.size() + 2) / 3 * 4);
    for (size_t i = 0; i < in.size(); i += 3) {
        uint32_t v = uint32_t(in[i]) << 16;
        if (i + 1 < in.size()) v |= uint32_t(in[i + 1]) << 8;
        if (i + 2 < in.size()) v |= in[i + 2];
        out += digits[(v >> 18) & 63];
        out += digits[(v >> 12) & 63];
        out += i + 1 < in.size() ? digits[(v >> 6) & 63] : '=';
        out += i + 2 < in.size() ? digits[v & 63] : '=';
    }
    return out;
}

// The writer's image callback: a data-URI image is written as one again;
// every other image keeps its uri / bufferView (returning false).
bool write_image(const std::string *, const std::string *, const tinygltf::Image *image, bool,
                 std::string *out_uri, void *)
{
    if (image->bufferView >= 0 || !image->uri.empty() || image->image.empty()) return false;
    std::string mime = image->mimeType.empty() ? "application/octet-stream" : image->mimeType;
    *out_uri = "data:" + mime + ";base64," + base64(image->image);
    return true;
}

// ---- the document ----

std::string folder_of(const char *name)
{
    std::string s = name ? name : "";
    if (s == "<stdin>") return "";
    size_t k = s.rfind('/');
    return k == std::string::npos ? std::string() : s.substr(0, k);
}

// The deepest nesting of JSON arrays and objects in [p, p + n) (strings
// skipped). tinygltf turns extras and extensions into its own values by
// recursion, one call per level: a hostile file nested a million deep
// would overflow the stack, so such a file is refused before parsing.
size_t json_depth(const char *p, size_t n)
{
    size_t depth = 0, deepest = 0;
    bool in_string = false;
    for (size_t i = 0; i < n; i++) {
        char c = p[i];
        if (in_string) {
            if (c == '\\') i++;
            else if (c == '"') in_string = false;
        } else if (c == '"') {
            in_string = true;
        } else if (c == '[' || c == '{') {
            deepest = std::max(deepest, ++depth);
        } else if ((c == ']' || c == '}') && depth > 0) {
            depth--;
        }
    }
    return deepest;
}

const size_t max_json_depth = 512;

void load(const char *data, size_t size, const char *name, tinygltf::Model &model)
{
    if (size > 0xffffffffu) refuse(SCAF_ERR_PARSE, "larger than 4 GiB, more than tinygltf reads");
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(keep_image, nullptr);
    std::string err, warn;
    bool binary = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
    bool ok;
    if (binary) {
        if (size < 20)
            refuse(SCAF_ERR_PARSE,
                   "truncated .glb (" + std::to_string(size) + " bytes, the header needs 20)");
        uint32_t json_length = 0;
        std::memcpy(&json_length, data + 12, 4); // the first chunk: JSON (checked by tinygltf)
        if (json_depth(data + 20, std::min<size_t>(json_length, size - 20)) > max_json_depth)
            refuse(SCAF_ERR_PARSE,
                   "JSON nested more than " + std::to_string(max_json_depth) + " levels deep");
        ok = loader.LoadBinaryFromMemory(&model, &err, &warn,
                                         reinterpret_cast<const unsigned char *>(data),
                                         unsigned(size), folder_of(name));
    } else {
        size_t i = 0;
        while (i < size &&
               (data[i] == ' ' || data[i] == '\t' || data[i] == '\r' || data[i] == '\n'))
            i++;
        if (i == size || data[i] != '{')
            refuse(SCAF_ERR_PARSE, "not glTF (neither the .glb magic 'glTF' nor a JSON object)");
        if (json_depth(data, size) > max_json_depth)
            refuse(SCAF_ERR_PARSE,
                   "JSON nested more than " + std::to_string(max_json_depth) + " levels deep");
        ok = loader.LoadASCIIFromString(&model, &err, &warn, data, unsigned(size), folder_of(name));
    }
    if (!ok) {
        while (!err.empty() && (err.back() == '\n' || err.back() == ' ')) err.pop_back();
        for (char &c : err)
            if (c == '\n') c = ';';
        refuse(SCAF_ERR_PARSE,
               "not valid glTF 2.0: " + (err.empty() ? std::string("tinygltf refused it") : err));
    }
}

// ---- accessors: every byte range checked before it is read ----

struct dense {
    std::vector<unsigned char> bytes; // count elements of elem bytes, tightly packed
    size_t count = 0, elem = 0;
    int components = 0, component_type = 0;
};

// The bytes of [offset, offset + length) of buffer view `view`, checked.
const unsigned char *view_range(const tinygltf::Model &model, int view, uint64_t offset,
                                uint64_t length, const std::string &what)
{
    if (view < 0 || size_t(view) >= model.bufferViews.size())
        refuse(SCAF_ERR_PARSE, what + ": buffer view " + std::to_string(view) + " does not exist");
    const tinygltf::BufferView &bv = model.bufferViews[size_t(view)];
    if (bv.buffer < 0 || size_t(bv.buffer) >= model.buffers.size())
        refuse(SCAF_ERR_PARSE, what + ": buffer " + std::to_string(bv.buffer) + " does not exist");
    const tinygltf::Buffer &b = model.buffers[size_t(bv.buffer)];
    uint64_t bo = bv.byteOffset, bl = bv.byteLength;
    if (bo > b.data.size() || bl > b.data.size() - bo)
        refuse(SCAF_ERR_PARSE,
               what + ": buffer view " + std::to_string(view) + " (bytes " + std::to_string(bo) +
                   " + " + std::to_string(bl) + ") lies outside its buffer of " +
                   std::to_string(b.data.size()) + " bytes");
    if (offset > bl || length > bl - offset)
        refuse(SCAF_ERR_PARSE,
               what + ": reads bytes " + std::to_string(offset) + " + " + std::to_string(length) +
                   " of buffer view " + std::to_string(view) + ", which has " + std::to_string(bl));
    return b.data.data() + bo + offset;
}

dense read_accessor(const tinygltf::Model &model, int index, const std::string &what)
{
    if (index < 0 || size_t(index) >= model.accessors.size())
        refuse(SCAF_ERR_PARSE, what + ": accessor " + std::to_string(index) + " does not exist");
    const tinygltf::Accessor &a = model.accessors[size_t(index)];
    std::string w = what + " (accessor " + std::to_string(index) + ")";
    dense d;
    int cs = tinygltf::GetComponentSizeInBytes(uint32_t(a.componentType));
    d.components = tinygltf::GetNumComponentsInType(uint32_t(a.type));
    if (cs <= 0 || d.components <= 0)
        refuse(SCAF_ERR_PARSE, w + ": unknown component type or type");
    d.component_type = a.componentType;
    d.elem = size_t(cs) * size_t(d.components);
    d.count = a.count;
    if (d.count > (size_t(1) << 31) / d.elem)
        refuse(SCAF_ERR_PARSE, w + ": count " + std::to_string(a.count) + " is absurd");
    d.bytes.assign(d.count * d.elem, 0);
    if (a.bufferView >= 0 && d.count > 0) {
        const tinygltf::BufferView &bv = a.bufferView < int(model.bufferViews.size())
            ? model.bufferViews[size_t(a.bufferView)]
            : tinygltf::BufferView();
        uint64_t stride = bv.byteStride ? bv.byteStride : d.elem;
        if (stride < d.elem)
            refuse(SCAF_ERR_PARSE,
                   w + ": byteStride " + std::to_string(stride) + " is smaller than one element (" +
                       std::to_string(d.elem) + " bytes)");
        uint64_t span = (uint64_t(d.count) - 1) * stride + d.elem;
        const unsigned char *p = view_range(model, a.bufferView, a.byteOffset, span, w);
        for (size_t i = 0; i < d.count; i++)
            std::memcpy(&d.bytes[i * d.elem], p + i * stride, d.elem);
    }
    if (a.sparse.isSparse) {
        size_t n = size_t(a.sparse.count);
        if (a.sparse.count < 0 || n > d.count)
            refuse(SCAF_ERR_PARSE, w + ": sparse count out of range");
        int ics = tinygltf::GetComponentSizeInBytes(uint32_t(a.sparse.indices.componentType));
        if (ics != 1 && ics != 2 && ics != 4) refuse(SCAF_ERR_PARSE, w + ": sparse index type");
        const unsigned char *ip = view_range(model, a.sparse.indices.bufferView,
                                             uint64_t(std::max(0, a.sparse.indices.byteOffset)),
                                             uint64_t(n) * uint64_t(ics), w + " sparse indices");
        const unsigned char *vp = view_range(model, a.sparse.values.bufferView,
                                             uint64_t(std::max(0, a.sparse.values.byteOffset)),
                                             uint64_t(n) * d.elem, w + " sparse values");
        for (size_t k = 0; k < n; k++) {
            uint32_t i = 0;
            if (ics == 1) i = ip[k];
            else if (ics == 2) {
                uint16_t s;
                std::memcpy(&s, ip + 2 * k, 2);
                i = s;
            } else std::memcpy(&i, ip + 4 * k, 4);
            if (i >= d.count)
                refuse(SCAF_ERR_PARSE, w + ": sparse index " + std::to_string(i) + " out of range");
            std::memcpy(&d.bytes[size_t(i) * d.elem], vp + k * d.elem, d.elem);
        }
    }
    return d;
}

// Component c of element i as a number (normalized integers scaled to [0, 1] / [-1, 1]).
double component(const dense &d, size_t i, int c, bool normalized)
{
    const unsigned char *p = &d.bytes[i * d.elem];
    int cs = int(d.elem) / d.components;
    p += size_t(c) * size_t(cs);
    switch (d.component_type) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT: {
        float f;
        std::memcpy(&f, p, 4);
        return f;
    }
    case TINYGLTF_COMPONENT_TYPE_DOUBLE: {
        double f;
        std::memcpy(&f, p, 8);
        return f;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return normalized ? p[0] / 255.0 : p[0];
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
        int8_t v;
        std::memcpy(&v, p, 1);
        return normalized ? std::max(v / 127.0, -1.0) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        uint16_t v;
        std::memcpy(&v, p, 2);
        return normalized ? v / 65535.0 : v;
    }
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
        int16_t v;
        std::memcpy(&v, p, 2);
        return normalized ? std::max(v / 32767.0, -1.0) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
        uint32_t v;
        std::memcpy(&v, p, 4);
        return v;
    }
    case TINYGLTF_COMPONENT_TYPE_INT: {
        int32_t v;
        std::memcpy(&v, p, 4);
        return v;
    }
    default: return 0;
    }
}

// ---- the scaf mesh of a document ----

struct piece {
    int mesh, prim;
    int first_face, faces;
    int first_vertex, vertices; // welded vertices in the scaf mesh
    int first_orig, origs;      // glTF vertices (the UV indices)
};

struct layout {
    std::vector<piece> pieces;
    std::vector<double> V, UV;
    std::vector<int> F, FT; // FT: the glTF vertex (global) of each corner
    int faces_without_uv = 0;
    bool uv = true;
};

std::string texcoord_name() { return "TEXCOORD_" + std::to_string(uv_set_index); }

layout build(const tinygltf::Model &model)
{
    layout L;
    int with_uv_faces = 0;
    for (size_t mi = 0; mi < model.meshes.size(); mi++) {
        const tinygltf::Mesh &me = model.meshes[mi];
        for (size_t pj = 0; pj < me.primitives.size(); pj++) {
            const tinygltf::Primitive &pr = me.primitives[pj];
            std::string w = where(int(mi), int(pj));
            if (pr.extensions.count("KHR_draco_mesh_compression"))
                refuse(SCAF_ERR_MESH,
                       w +
                           " is Draco-compressed (KHR_draco_mesh_compression), which scaf cannot "
                           "decode: write the file uncompressed");
            static const char *const modes[] = {"POINTS",      "LINES",     "LINE_LOOP",
                                                "LINE_STRIP",  "TRIANGLES", "TRIANGLE_STRIP",
                                                "TRIANGLE_FAN"};
            if (pr.mode != TINYGLTF_MODE_TRIANGLES)
                refuse(SCAF_ERR_MESH,
                       w + " has mode " +
                           (pr.mode >= 0 && pr.mode <= 6 ? modes[pr.mode]
                                                         : std::to_string(pr.mode).c_str()) +
                           ": scaf maps TRIANGLES only" +
                           (pr.mode == 5 || pr.mode == 6 ? " (convert the strip or fan to "
                                                           "TRIANGLES)"
                                                         : ""));
            auto pos = pr.attributes.find("POSITION");
            if (pos == pr.attributes.end()) refuse(SCAF_ERR_PARSE, w + " has no POSITION");
            const tinygltf::Accessor *pa =
                pos->second >= 0 && size_t(pos->second) < model.accessors.size()
                ? &model.accessors[size_t(pos->second)]
                : nullptr;
            if (pa &&
                (pa->componentType != TINYGLTF_COMPONENT_TYPE_FLOAT ||
                 pa->type != TINYGLTF_TYPE_VEC3))
                refuse(SCAF_ERR_MESH,
                       w +
                           ": POSITION is not FLOAT VEC3 (quantized positions, "
                           "KHR_mesh_quantization, are not supported)");
            dense P = read_accessor(model, pos->second, w + " POSITION");
            piece pc{int(mi),
                     int(pj),
                     int(L.F.size() / 3),
                     0,
                     int(L.V.size() / 3),
                     0,
                     int(L.UV.size() / 2),
                     int(P.count)};
            if (uint64_t(L.UV.size() / 2) + P.count > uint64_t(INT32_MAX / 2))
                refuse(SCAF_ERR_PARSE, w + ": too many vertices");
            // vertices at bitwise the same position: one scaf vertex
            std::map<std::array<uint64_t, 3>, int> at;
            std::vector<int> welded(P.count);
            for (size_t i = 0; i < P.count; i++) {
                double x[3];
                std::array<uint64_t, 3> key;
                for (int c = 0; c < 3; c++) {
                    x[c] = component(P, i, c, false);
                    if (!std::isfinite(x[c]))
                        refuse(SCAF_ERR_PARSE,
                               w + ": POSITION " + std::to_string(i) + " is not finite");
                    std::memcpy(&key[size_t(c)], &x[c], 8);
                }
                auto it = at.emplace(key, pc.vertices);
                if (it.second) {
                    L.V.insert(L.V.end(), x, x + 3);
                    pc.vertices++;
                }
                welded[i] = pc.first_vertex + it.first->second;
            }
            // triangles
            std::vector<uint32_t> idx;
            if (pr.indices >= 0) {
                dense I = read_accessor(model, pr.indices, w + " indices");
                if (I.components != 1 ||
                    (I.component_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
                     I.component_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
                     I.component_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT))
                    refuse(SCAF_ERR_PARSE, w + ": indices are not unsigned integer scalars");
                idx.resize(I.count);
                for (size_t k = 0; k < I.count; k++) {
                    double v = component(I, k, 0, false);
                    if (v >= double(P.count))
                        refuse(SCAF_ERR_PARSE,
                               w + ": index " + std::to_string(k) + " is " +
                                   std::to_string(uint64_t(v)) +
                                   ", out of range (the primitive has " + std::to_string(P.count) +
                                   " vertices)");
                    idx[k] = uint32_t(v);
                }
            } else {
                idx.resize(P.count);
                for (size_t k = 0; k < P.count; k++) idx[k] = uint32_t(k);
            }
            if (idx.size() % 3 != 0)
                refuse(SCAF_ERR_PARSE,
                       w + ": " + std::to_string(idx.size()) +
                           " indices, not a multiple of 3 (TRIANGLES)");
            if (idx.empty()) refuse(SCAF_ERR_MESH, w + " has no triangles");
            if (L.F.size() / 3 + idx.size() / 3 > size_t(INT32_MAX / 3))
                refuse(SCAF_ERR_PARSE, w + ": too many triangles");
            for (size_t t = 0; t < idx.size(); t += 3) {
                int a = welded[idx[t]], b = welded[idx[t + 1]], c = welded[idx[t + 2]];
                if (a == b || b == c || a == c)
                    refuse(SCAF_ERR_MESH,
                           w + ": triangle " + std::to_string(t / 3) +
                               " has two corners at the same position (vertices " +
                               std::to_string(idx[t]) + ", " + std::to_string(idx[t + 1]) + ", " +
                               std::to_string(idx[t + 2]) + "): a degenerate triangle");
                L.F.insert(L.F.end(), {a, b, c});
                for (int k = 0; k < 3; k++) L.FT.push_back(pc.first_orig + int(idx[t + size_t(k)]));
            }
            pc.faces = int(idx.size() / 3);
            // the input UVs of this primitive, one per glTF vertex
            auto tc = pr.attributes.find(texcoord_name());
            L.UV.resize(L.UV.size() + 2 * P.count, 0.0);
            if (tc == pr.attributes.end()) {
                L.faces_without_uv += pc.faces;
            } else {
                const tinygltf::Accessor &ta = model.accessors.at(size_t(std::max(0, tc->second)));
                dense T = read_accessor(model, tc->second, w + " " + texcoord_name());
                if (T.components != 2 || T.count != P.count)
                    refuse(SCAF_ERR_PARSE,
                           w + ": " + texcoord_name() + " is not one VEC2 per vertex");
                for (size_t i = 0; i < P.count; i++) {
                    double u = component(T, i, 0, ta.normalized),
                           v = component(T, i, 1, ta.normalized);
                    if (!std::isfinite(u) || !std::isfinite(v))
                        refuse(SCAF_ERR_PARSE,
                               w + ": " + texcoord_name() + " " + std::to_string(i) +
                                   " is not finite");
                    L.UV[2 * (size_t(pc.first_orig) + i)] = u;
                    L.UV[2 * (size_t(pc.first_orig) + i) + 1] = 1.0 - v; // glTF's v runs down
                }
                with_uv_faces += pc.faces;
            }
            L.pieces.push_back(pc);
        }
    }
    if (L.pieces.empty()) refuse(SCAF_ERR_MESH, "no mesh primitive: nothing to map");
    L.uv = with_uv_faces > 0 && L.faces_without_uv == 0;
    if (with_uv_faces == 0) L.faces_without_uv = 0;
    return L;
}

scaf_status status_of(const char *name, scaf_error *err, const fail &f)
{
    return err_set(err, f.status, "%s: %s", name, f.message.c_str());
}

// ---- writing ----

// Append bytes to buffer 0 as a new buffer view (4-byte aligned; elements
// of a size that is not a multiple of 4 padded to a stride that is, as
// glTF requires of vertex attributes). Returns the view's index.
int append_view(tinygltf::Model &model, const std::vector<unsigned char> &packed, size_t elem,
                size_t count, int target)
{
    if (model.buffers.empty()) model.buffers.emplace_back();
    std::vector<unsigned char> &b = model.buffers[0].data;
    while (b.size() % 4) b.push_back(0);
    size_t stride = target == TINYGLTF_TARGET_ARRAY_BUFFER ? (elem + 3) / 4 * 4 : elem;
    tinygltf::BufferView bv;
    bv.buffer = 0;
    bv.byteOffset = b.size();
    for (size_t i = 0; i < count; i++) {
        b.insert(b.end(), packed.begin() + long(i * elem), packed.begin() + long((i + 1) * elem));
        for (size_t k = elem; k < stride; k++) b.push_back(0);
    }
    bv.byteLength = b.size() - bv.byteOffset;
    if (stride != elem) bv.byteStride = stride;
    bv.target = target;
    model.bufferViews.push_back(bv);
    return int(model.bufferViews.size() - 1);
}

// A copy of accessor `from` gathered at the glTF vertices `src` (count
// src.size()), with min / max recomputed when it had them or is POSITION.
int gathered(tinygltf::Model &model, int from, const std::vector<int> &src, bool position,
             const std::string &what)
{
    dense d = read_accessor(model, from, what);
    const tinygltf::Accessor old = model.accessors[size_t(from)];
    std::vector<unsigned char> out(src.size() * d.elem);
    for (size_t i = 0; i < src.size(); i++) {
        if (size_t(src[i]) >= d.count)
            refuse(SCAF_ERR_PARSE, what + ": fewer elements than POSITION");
        std::memcpy(&out[i * d.elem], &d.bytes[size_t(src[i]) * d.elem], d.elem);
    }
    tinygltf::Accessor a;
    a.name = old.name;
    a.componentType = old.componentType;
    a.type = old.type;
    a.normalized = old.normalized;
    a.count = src.size();
    a.bufferView = append_view(model, out, d.elem, src.size(), TINYGLTF_TARGET_ARRAY_BUFFER);
    if (position || !old.minValues.empty() || !old.maxValues.empty()) {
        dense g = d;
        g.bytes = out;
        g.count = src.size();
        a.minValues.assign(size_t(d.components), INFINITY);
        a.maxValues.assign(size_t(d.components), -INFINITY);
        for (size_t i = 0; i < g.count; i++)
            for (int c = 0; c < d.components; c++) {
                double v = component(g, i, c, false);
                a.minValues[size_t(c)] = std::min(a.minValues[size_t(c)], v);
                a.maxValues[size_t(c)] = std::max(a.maxValues[size_t(c)], v);
            }
        if (g.count == 0) a.minValues.clear(), a.maxValues.clear();
    }
    model.accessors.push_back(a);
    return int(model.accessors.size() - 1);
}

void rewrite(tinygltf::Model &model, const layout &L, const mesh *m)
{
    if (m->nf != int(L.F.size() / 3) || m->nv != int(L.V.size() / 3) || !mesh_has_uv(m) ||
        std::memcmp(m->F, L.F.data(), L.F.size() * sizeof(int)) != 0)
        refuse(SCAF_ERR_MESH,
               "the mesh is not the one read from this document (did the file change?)");
    for (const piece &pc : L.pieces) {
        tinygltf::Primitive &pr = model.meshes[size_t(pc.mesh)].primitives[size_t(pc.prim)];
        std::string w = where(pc.mesh, pc.prim);
        // one new vertex per (glTF vertex, new UV) pair, in corner order
        std::map<std::pair<int, int>, uint32_t> id;
        std::vector<int> src;
        std::vector<int> uvof;
        std::vector<uint32_t> idx;
        for (int f = pc.first_face; f < pc.first_face + pc.faces; f++)
            for (int k = 0; k < 3; k++) {
                size_t c = 3 * size_t(f) + size_t(k);
                int orig = L.FT[c] - pc.first_orig, t = m->FT[c];
                if (t < 0 || t >= m->nuv) refuse(SCAF_ERR_MESH, w + ": a UV index out of range");
                auto it = id.emplace(std::make_pair(orig, t), uint32_t(src.size()));
                if (it.second) {
                    src.push_back(orig);
                    uvof.push_back(t);
                }
                idx.push_back(it.first->second);
            }
        std::string tcn = texcoord_name();
        std::map<std::string, int> attrs;
        for (const auto &at : pr.attributes)
            if (at.first != tcn)
                attrs[at.first] =
                    gathered(model, at.second, src, at.first == "POSITION", w + " " + at.first);
        for (auto &target : pr.targets)
            for (auto &at : target)
                at.second = gathered(model, at.second, src, at.first == "POSITION",
                                     w + " morph target " + at.first);
        // the new UVs: FLOAT VEC2 (u, 1 - v)
        std::vector<unsigned char> uvb(src.size() * 8);
        for (size_t i = 0; i < src.size(); i++) {
            const double *t = m->UV + 2 * size_t(uvof[i]);
            if (!std::isfinite(t[0]) || !std::isfinite(t[1]))
                refuse(SCAF_ERR_MESH, w + ": a UV is not finite");
            float uv[2] = {float(t[0]), float(1.0 - t[1])};
            std::memcpy(&uvb[8 * i], uv, 8);
        }
        tinygltf::Accessor ta;
        ta.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
        ta.type = TINYGLTF_TYPE_VEC2;
        ta.count = src.size();
        ta.bufferView = append_view(model, uvb, 8, src.size(), TINYGLTF_TARGET_ARRAY_BUFFER);
        model.accessors.push_back(ta);
        attrs[tcn] = int(model.accessors.size() - 1);
        // the indices
        bool wide = src.size() > 65535;
        std::vector<unsigned char> ib(idx.size() * (wide ? 4 : 2));
        for (size_t k = 0; k < idx.size(); k++) {
            if (wide) std::memcpy(&ib[4 * k], &idx[k], 4);
            else {
                uint16_t s = uint16_t(idx[k]);
                std::memcpy(&ib[2 * k], &s, 2);
            }
        }
        tinygltf::Accessor ia;
        ia.componentType =
            wide ? TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT : TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
        ia.type = TINYGLTF_TYPE_SCALAR;
        ia.count = idx.size();
        ia.bufferView =
            append_view(model, ib, wide ? 4 : 2, idx.size(), TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
        model.accessors.push_back(ia);
        pr.indices = int(model.accessors.size() - 1);
        pr.attributes = attrs;
    }
}

} // namespace

extern "C" {

void gltf_set_uv_set(int n) { uv_set_index = n < 0 ? 0 : n; }
int gltf_uv_set(void) { return uv_set_index; }

scaf_status gltf_parse(const char *data, size_t size, const char *name, mesh *m,
                       int *faces_without_uv, scaf_error *err)
{
    std::memset(m, 0, sizeof *m);
    if (faces_without_uv) *faces_without_uv = 0;
    if (!name) name = "<memory>";
    try {
        tinygltf::Model model;
        load(data, size, name, model);
        layout L = build(model);
        int nuv = L.uv ? int(L.UV.size() / 2) : 0;
        if (mesh_alloc(m, int(L.V.size() / 3), int(L.F.size() / 3), nuv, err) != SCAF_OK)
            return SCAF_ERR_NOMEM;
        std::memcpy(m->V, L.V.data(), L.V.size() * sizeof(double));
        std::memcpy(m->F, L.F.data(), L.F.size() * sizeof(int));
        if (nuv) {
            std::memcpy(m->UV, L.UV.data(), L.UV.size() * sizeof(double));
            std::memcpy(m->FT, L.FT.data(), L.FT.size() * sizeof(int));
        }
        if (faces_without_uv) *faces_without_uv = L.faces_without_uv;
        return SCAF_OK;
    } catch (const fail &f) {
        mesh_free(m);
        return status_of(name, err, f);
    } catch (const std::bad_alloc &) {
        mesh_free(m);
        return err_set(err, SCAF_ERR_NOMEM, "%s: out of memory reading glTF", name);
    } catch (const std::exception &e) {
        mesh_free(m);
        return err_set(err, SCAF_ERR_PARSE, "%s: not valid glTF 2.0: %s", name, e.what());
    }
}

scaf_status gltf_pieces(const char *data, size_t size, const char *name, gltf_piece **pieces,
                        int *n, scaf_error *err)
{
    *pieces = nullptr;
    *n = 0;
    if (!name) name = "<memory>";
    try {
        tinygltf::Model model;
        load(data, size, name, model);
        layout L = build(model);
        gltf_piece *p = static_cast<gltf_piece *>(std::calloc(L.pieces.size(), sizeof *p));
        if (!p) throw std::bad_alloc();
        for (size_t k = 0; k < L.pieces.size(); k++) {
            p[k].mesh = L.pieces[k].mesh;
            p[k].primitive = L.pieces[k].prim;
            std::snprintf(p[k].mesh_name, sizeof p[k].mesh_name, "%s",
                          model.meshes[size_t(p[k].mesh)].name.c_str());
            p[k].first_face = L.pieces[k].first_face;
            p[k].faces = L.pieces[k].faces;
        }
        *pieces = p;
        *n = int(L.pieces.size());
        return SCAF_OK;
    } catch (const fail &f) {
        return status_of(name, err, f);
    } catch (const std::bad_alloc &) {
        return err_set(err, SCAF_ERR_NOMEM, "%s: out of memory reading glTF", name);
    } catch (const std::exception &e) {
        return err_set(err, SCAF_ERR_PARSE, "%s: not valid glTF 2.0: %s", name, e.what());
    }
}

scaf_status gltf_rewrite_uv(const char *data, size_t size, const char *name, const mesh *m,
                            const char *out_path, int binary, scaf_error *err)
{
    if (!name) name = "<memory>";
    std::string bytes;
    try {
        tinygltf::Model model;
        load(data, size, name, model);
        layout L = build(model);
        rewrite(model, L, m);
        if (binary && !model.buffers.empty()) model.buffers[0].uri.clear(); // the BIN chunk
        tinygltf::TinyGLTF writer;
        writer.SetImageWriter(write_image, nullptr);
        std::ostringstream os;
        if (!writer.WriteGltfSceneToStream(&model, os, true, binary != 0))
            refuse(SCAF_ERR_INTERNAL, "tinygltf could not serialize the document");
        bytes = os.str();
    } catch (const fail &f) {
        return status_of(name, err, f);
    } catch (const std::bad_alloc &) {
        return err_set(err, SCAF_ERR_NOMEM, "%s: out of memory writing glTF", out_path);
    } catch (const std::exception &e) {
        return err_set(err, SCAF_ERR_INTERNAL, "%s: glTF serialization failed: %s", out_path,
                       e.what());
    }
    atomic_file af;
    scaf_status st = atomic_open(&af, out_path, err);
    if (st != SCAF_OK) return st;
    if (std::fwrite(bytes.data(), 1, bytes.size(), af.f) != bytes.size()) {
        atomic_abort(&af);
        return err_set(err, SCAF_ERR_IO, "%s: cannot write (disk full?)", out_path);
    }
    return atomic_commit(&af, err);
}

} // extern "C"
