// CURVETEXT_API marks the public API: curvetext is compiled with hidden
// symbols, so a shared build exports what carries this mark and nothing else.
//
// Conventions of every public header (curvetext/*.hpp); each declaration's
// comment says where it differs or adds to them:
//  - Errors: failures the caller can act on are thrown as curvetext::Error
//    (error.hpp) with the codes the comment names; any function may also
//    throw std::bad_alloc. A function whose comment names no error throws
//    nothing else.
//  - Ownership and lifetime: results are returned by value and owned by the
//    caller; arguments passed by reference, pointer or span are only read
//    (or written) during the call, unless the comment says they are kept.
//  - Thread safety: free functions without GL, and value types (structs,
//    Outline, Transform, Image, Paragraph), may be used from several threads
//    at once on distinct objects, and on one object when every use is const.
//    Classes state their own rule. Whatever draws or uploads (Renderer,
//    DrawBatch, GlyphCache's GPU buffers, render_*_image, HeadlessContext)
//    uses the GL context current on the calling thread.
//  - Units: outlines, meshes and shaped glyph positions are in font (or
//    document) units, y up; layout, placements and images in pixels, y down,
//    pixel (i, j) covering [i, i+1] x [j, j+1]; positions in text are UTF-8
//    byte offsets, and code point indices where the text is a u32string_view.
#pragma once

// CURVETEXT_HIDDEN keeps a marked class's nested implementation (its `struct
// Impl`) out of the export, which it would otherwise inherit.
#if defined(_WIN32)
#if defined(CURVETEXT_SHARED) && defined(CURVETEXT_BUILDING)
#define CURVETEXT_API __declspec(dllexport)
#elif defined(CURVETEXT_SHARED)
#define CURVETEXT_API __declspec(dllimport)
#else
#define CURVETEXT_API
#endif
#define CURVETEXT_HIDDEN
#else
#define CURVETEXT_API __attribute__((visibility("default")))
#define CURVETEXT_HIDDEN __attribute__((visibility("hidden")))
#endif
