/* app/pixel_font: short labels drawn into pixel buffers (the legends of
 * the PNG pictures: colour-bar ticks, chart numbers, panel captions).
 *
 * A 3 by 5 pixel glyph per character, drawn scale times larger, one blank
 * column between characters. Digits, letters (lower case drawn as upper
 * case) and ". - + = : / ( ) , % < >"; any other character is a blank.
 * Pixels outside the buffer are skipped, so a label may be clipped but
 * never writes out of bounds. Nothing fails.
 */
#ifndef SCAF_APP_PIXEL_FONT_H
#define SCAF_APP_PIXEL_FONT_H

/* Pixels of text drawn at scale (>= 1): width and height. */
int pixel_font_width(const char *text, int scale);
int pixel_font_height(int scale);

/* Draw text with its top-left corner at (x, y) into px: height rows of
 * width pixels of channels (3: RGB, 4: RGBA, alpha set opaque) bytes,
 * top row first, in colour 0xRRGGBB. */
void pixel_font_draw(unsigned char *px, int width, int height, int channels, int x, int y,
                     const char *text, int scale, unsigned colour);

/* A filled rectangle [x, x + w) by [y, y + h), clipped (same buffer). */
void pixel_fill_rect(unsigned char *px, int width, int height, int channels, int x, int y, int w,
                     int h, unsigned colour);

#endif /* SCAF_APP_PIXEL_FONT_H */
