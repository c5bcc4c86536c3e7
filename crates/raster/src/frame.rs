//! The frame buffer: one byte per pixel, row-major, row `j` holding y in `[j, j + 1)`.

/// Default width, the resolution Vatti's Table 3 fits its polygons in.
pub const DEFAULT_WIDTH: usize = 1280;
/// Default height.
pub const DEFAULT_HEIGHT: usize = 1024;

/// A grid of pixels, one byte each (0 is unlit). Pixel `(i, j)` covers `[i, i + 1) x [j, j + 1)`
/// of the plane; its centre is `(i + 0.5, j + 0.5)`.
#[derive(Clone, PartialEq, Eq)]
pub struct FrameBuffer {
    width: usize,
    height: usize,
    pixels: Vec<u8>,
}

impl FrameBuffer {
    /// A cleared buffer of `width x height` pixels.
    pub fn new(width: usize, height: usize) -> FrameBuffer {
        FrameBuffer { width, height, pixels: vec![0; width * height] }
    }

    /// Width in pixels.
    pub fn width(&self) -> usize {
        self.width
    }

    /// Height in pixels.
    pub fn height(&self) -> usize {
        self.height
    }

    /// Sets every pixel to 0.
    pub fn clear(&mut self) {
        self.pixels.fill(0);
    }

    /// The value of pixel `(i, j)`, 0 outside the buffer.
    pub fn get(&self, i: usize, j: usize) -> u8 {
        if i < self.width && j < self.height { self.pixels[j * self.width + i] } else { 0 }
    }

    /// Sets pixel `(i, j)` to `value`; a pixel outside the buffer is skipped, as the fills skip
    /// rows and columns outside it.
    pub fn set(&mut self, i: usize, j: usize, value: u8) {
        if i < self.width && j < self.height {
            self.pixels[j * self.width + i] = value;
        }
    }

    /// All pixels, row by row.
    pub fn pixels(&self) -> &[u8] {
        &self.pixels
    }

    /// Number of lit (non-zero) pixels.
    pub fn lit_count(&self) -> usize {
        self.pixels.iter().filter(|&&v| v != 0).count()
    }

    /// A 64-bit FNV-1a hash of the size and every pixel, to compare renderings cheaply.
    pub fn checksum(&self) -> u64 {
        let mut hash: u64 = 0xcbf2_9ce4_8422_2325;
        let size = [self.width as u64, self.height as u64];
        for byte in size.iter().flat_map(|v| v.to_le_bytes()).chain(self.pixels.iter().copied()) {
            hash = (hash ^ u64::from(byte)).wrapping_mul(0x0100_0000_01b3);
        }
        hash
    }

    /// Sets pixels `columns` of row `row` to `value`; the caller has clipped both to the buffer.
    #[inline]
    pub(crate) fn fill_span(&mut self, row: usize, columns: core::ops::Range<usize>, value: u8) {
        let start = row * self.width;
        self.pixels[start + columns.start..start + columns.end].fill(value);
    }
}

impl Default for FrameBuffer {
    /// A cleared 1280 x 1024 buffer.
    fn default() -> FrameBuffer {
        FrameBuffer::new(DEFAULT_WIDTH, DEFAULT_HEIGHT)
    }
}

impl core::fmt::Debug for FrameBuffer {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("FrameBuffer")
            .field("width", &self.width)
            .field("height", &self.height)
            .field("lit", &self.lit_count())
            .field("checksum", &self.checksum())
            .finish()
    }
}
