"""The bytes of a user's file as UTF-8 text, or what they are instead.

Every reader of a user's text file (robot descriptions, controller YAML, scenarios, sweeps,
drive scripts) decodes here, so a UTF-16 file, an image or a Latin-1 comment gets the same
one-line diagnosis everywhere. A UTF-8 byte-order mark is dropped, as PyYAML and expat accept
it.
"""

from __future__ import annotations

import codecs

_BOMS = ((codecs.BOM_UTF32_LE, "UTF-32"), (codecs.BOM_UTF32_BE, "UTF-32"),
         (codecs.BOM_UTF16_LE, "UTF-16"), (codecs.BOM_UTF16_BE, "UTF-16"))
"""UTF-32 first: its little-endian mark starts with UTF-16's."""

_MAGIC = ((b"\x89PNG\r\n\x1a\n", "a PNG image"), (b"\xff\xd8\xff", "a JPEG image"),
          (b"GIF8", "a GIF image"), (b"%PDF-", "a PDF document"),
          (b"PK\x03\x04", "a ZIP archive"), (b"\x1f\x8b", "a gzip archive"),
          (b"BZh", "a bzip2 archive"), (b"\xfd7zXZ\x00", "an xz archive"),
          (b"7z\xbc\xaf\x27\x1c", "a 7-Zip archive"), (b"\x28\xb5\x2f\xfd", "a zstd archive"),
          (b"\x7fELF", "an executable (ELF)"), (b"\x89HDF", "an HDF5 file"),
          (b"SQLite format 3\x00", "an SQLite database"))
"""Signatures of common binary files, by their first bytes."""

_SNIFF_BYTES = 8192
"""How much of the start is searched for NUL bytes, which text never holds."""


class NotUtf8(ValueError):
    """Bytes that are not UTF-8 text.

    Attributes:
        what: What the bytes are, for a message: ``UTF-16 text (it starts with a UTF-16
            byte-order mark)``, ``a PNG image``, ``binary data (it holds NUL bytes)`` or
            ``byte 0xe9, 'é' in Latin-1``.
        binary: True when the content is not text at all: saving it as UTF-8 cannot help.
        line: 1-based line of the first byte that is not UTF-8; 0 for the whole file.
        column: 1-based column (in bytes) of that byte; 0 for the whole file.
    """

    def __init__(self, what: str, *, binary: bool = False, line: int = 0,
                 column: int = 0) -> None:
        super().__init__(what)
        self.what, self.binary, self.line, self.column = what, binary, line, column


def decode_utf8(data: bytes) -> str:
    """``data`` as text; a leading UTF-8 byte-order mark is dropped.

    Raises:
        NotUtf8: UTF-16 or UTF-32 text, a known binary format, NUL bytes, or a byte sequence
            that is not UTF-8 (with its line and column).
    """
    try:
        text = data.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        raise _diagnosis(data, exc.start) from None
    if b"\0" in data[:_SNIFF_BYTES]:  # the same bytes _diagnosis looks at
        raise _diagnosis(data, None)
    return text


def _diagnosis(data: bytes, bad: int | None) -> NotUtf8:
    """What ``data`` is, its first non-UTF-8 byte at offset ``bad`` (None: it decoded)."""
    for bom, encoding in _BOMS:
        if data.startswith(bom):
            return NotUtf8(f"{encoding} text (it starts with a {encoding} byte-order mark)")
    for magic, kind in _MAGIC:
        if data.startswith(magic):
            return NotUtf8(kind, binary=True)
    start = data[:_SNIFF_BYTES]
    if b"\0" in start:
        even, odd = bool(start[0::2].strip(b"\0")), bool(start[1::2].strip(b"\0"))
        if even != odd:  # ASCII in UTF-16 without a byte-order mark
            return NotUtf8("UTF-16 text without a byte-order mark (every other byte is NUL)")
        return NotUtf8("binary data (it holds NUL bytes)", binary=True)
    assert bad is not None  # bytes that decoded and hold no NUL were returned as text
    before = data[:bad]
    line = before.count(b"\n") + 1
    column = bad - (before.rfind(b"\n") + 1) + 1
    return NotUtf8(f"byte 0x{data[bad]:02x}{_as_latin1(data[bad])}", line=line, column=column)


def _as_latin1(byte: int) -> str:
    """``, 'é' in Latin-1`` for a printable Latin-1 letter or sign, else nothing."""
    return f", '{bytes([byte]).decode('latin-1')}' in Latin-1" if byte >= 0xA0 else ""
