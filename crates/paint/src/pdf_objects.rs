//! A PDF document written to its output object by object, as it is made, instead of
//! built whole in memory: the objects go through one `pdf-writer` chunk handed on to the
//! output every [`BATCH`] bytes, their offsets noted for the cross-reference table. The
//! bytes are those `pdf_writer::Pdf` writes for the same objects in the same order
//! (header, objects, the cross-reference table with its free list, the trailer).

use std::io::{self, Write};

use pdf_writer::{Chunk, Ref};

/// Bytes gathered before they are handed on to the output.
const BATCH: usize = 1 << 20;

/// The header `pdf_writer::Pdf` starts a document with (version 1.7, a binary marker).
const HEADER: &[u8] = b"%PDF-1.7\n%\x80\x80\x80\x80\n\n";

/// A document being written to `out`.
pub(crate) struct ObjectWriter<'w> {
    out: &'w mut dyn Write,
    chunk: Chunk,
    /// Bytes already handed on to `out`.
    written: usize,
    /// Each object's id and offset in the file.
    offsets: Vec<(Ref, usize)>,
}

impl<'w> ObjectWriter<'w> {
    /// A document with its header written.
    pub(crate) fn new(out: &'w mut dyn Write) -> io::Result<Self> {
        out.write_all(HEADER)?;
        Ok(ObjectWriter {
            out,
            chunk: Chunk::with_capacity(BATCH + BATCH / 8),
            written: HEADER.len(),
            offsets: Vec::new(),
        })
    }

    /// The chunk to write object `id` into, next, and only it: its offset is noted.
    pub(crate) fn object(&mut self, id: Ref) -> io::Result<&mut Chunk> {
        if self.chunk.len() >= BATCH {
            self.hand_on()?;
        }
        self.offsets.push((id, self.written + self.chunk.len()));
        Ok(&mut self.chunk)
    }

    /// Writes the chunk's bytes to the output and starts an empty one.
    fn hand_on(&mut self) -> io::Result<()> {
        self.out.write_all(self.chunk.as_bytes())?;
        self.written += self.chunk.len();
        self.chunk = Chunk::with_capacity(BATCH + BATCH / 8);
        Ok(())
    }

    /// Writes the cross-reference table and the trailer (`catalog` its root) as
    /// `pdf_writer::Pdf::finish` does; returns the document's length in bytes.
    pub(crate) fn finish(mut self, catalog: Ref) -> io::Result<u64> {
        self.out.write_all(self.chunk.as_bytes())?;
        self.written += self.chunk.len();
        self.chunk = Chunk::new();
        let mut offsets = std::mem::take(&mut self.offsets);
        offsets.sort();
        let xref_len = 1 + offsets.last().map_or(0, |p| p.0.get());
        let xref_offset = self.written;
        let mut buf: Vec<u8> = Vec::with_capacity(BATCH + 64);
        write!(buf, "xref\n0 {xref_len}\n")?;
        if offsets.is_empty() {
            buf.extend_from_slice(b"0000000000 65535 f\r\n");
        }
        let mut listed = 0;
        for (i, (id, offset)) in offsets.iter().enumerate() {
            if listed > id.get() {
                return Err(io::Error::other(format!(
                    "PDF object {} written twice",
                    id.get()
                )));
            }
            // The free list: ids not written, each naming the next free one.
            for free in listed..id.get() {
                let mut next = free + 1;
                if next == id.get() {
                    for (used, _) in &offsets[i..] {
                        if next < used.get() {
                            break;
                        }
                        next = used.get() + 1;
                    }
                }
                let generation = if free == 0 { "65535" } else { "00000" };
                write!(buf, "{:010} {generation} f\r\n", next % xref_len)?;
            }
            write!(buf, "{offset:010} 00000 n\r\n")?;
            listed = id.get() + 1;
            if buf.len() >= BATCH {
                self.out.write_all(&buf)?;
                self.written += buf.len();
                buf.clear();
            }
        }
        write!(
            buf,
            "trailer\n<<\n  /Size {xref_len}\n  /Root {} 0 R\n>>\nstartxref\n{xref_offset}\n%%EOF",
            catalog.get()
        )?;
        self.out.write_all(&buf)?;
        self.written += buf.len();
        self.out.flush()?;
        Ok(self.written as u64)
    }
}

#[cfg(test)]
mod tests {
    use pdf_writer::{Pdf, Rect};

    use super::*;

    /// The same objects through `pdf_writer::Pdf` and through an [`ObjectWriter`]: ids
    /// out of order and a gap (object 4 never written: a free-list entry), a stream
    /// larger than a batch (handed on before the next object).
    #[test]
    fn same_bytes_as_pdf_writer() {
        let big = vec![b'x'; BATCH + 17];
        let catalog = Ref::new(1);
        let pages = Ref::new(2);
        let page = Ref::new(3);
        let stream = Ref::new(6);
        let state = Ref::new(5);

        let mut pdf = Pdf::new();
        pdf.catalog(catalog).pages(pages);
        pdf.pages(pages).kids([page]).count(1);
        pdf.page(page)
            .media_box(Rect::new(0.0, 0.0, 10.0, 20.0))
            .parent(pages)
            .contents(stream);
        pdf.stream(stream, &big);
        pdf.ext_graphics(state).non_stroking_alpha(0.5);
        let expected = pdf.finish();

        let mut out = Vec::new();
        let mut w = ObjectWriter::new(&mut out).unwrap();
        w.object(catalog)
            .unwrap()
            .indirect(catalog)
            .start::<pdf_writer::writers::Catalog>()
            .pages(pages);
        w.object(pages).unwrap().pages(pages).kids([page]).count(1);
        w.object(page)
            .unwrap()
            .page(page)
            .media_box(Rect::new(0.0, 0.0, 10.0, 20.0))
            .parent(pages)
            .contents(stream);
        w.object(stream).unwrap().stream(stream, &big);
        w.object(state)
            .unwrap()
            .ext_graphics(state)
            .non_stroking_alpha(0.5);
        let length = w.finish(catalog).unwrap();
        assert_eq!(length, out.len() as u64);
        assert!(out == expected, "the documents differ");
    }

    /// An object written twice is an error, not a broken table.
    #[test]
    fn an_object_written_twice_is_refused() {
        let mut out = Vec::new();
        let mut w = ObjectWriter::new(&mut out).unwrap();
        let r = Ref::new(1);
        w.object(r).unwrap().ext_graphics(r).non_stroking_alpha(0.5);
        w.object(r)
            .unwrap()
            .ext_graphics(r)
            .non_stroking_alpha(0.25);
        assert!(w.finish(r).is_err());
    }
}
