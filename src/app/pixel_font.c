/* app/pixel_font: see pixel_font.h. Each glyph is 15 characters, five
 * rows of three, '#' for a lit pixel. */
#include "app/pixel_font.h"

#include <ctype.h>
#include <string.h>

typedef struct glyph {
    char c;
    const char *rows;
} glyph;

static const glyph GLYPHS[] = {
    {'0', "####.##.##.####"}, {'1', ".#.##..#..#.###"}, {'2', "###..#####..###"},
    {'3', "###..#.##..####"}, {'4', "#.##.####..#..#"}, {'5', "####..###..####"},
    {'6', "####..####.####"}, {'7', "###..#.#..#..#."}, {'8', "####.#####.####"},
    {'9', "####.####..####"}, {'A', ".#.#.#####.##.#"}, {'B', "##.#.###.#.###."},
    {'C', ".###..#..#...##"}, {'D', "##.#.##.##.###."}, {'E', "####..##.#..###"},
    {'F', "####..##.#..#.."}, {'G', ".###..#.##.#.##"}, {'H', "#.##.#####.##.#"},
    {'I', "###.#..#..#.###"}, {'J', "..#..#..##.#.#."}, {'K', "#.##.###.#.##.#"},
    {'L', "#..#..#..#..###"}, {'M', "#.########.##.#"}, {'N', "##.#.##.##.##.#"},
    {'O', ".#.#.##.##.#.#."}, {'P', "##.#.###.#..#.."}, {'Q', ".#.#.##.###..##"},
    {'R', "##.#.###.#.##.#"}, {'S', ".###...#...###."}, {'T', "###.#..#..#..#."},
    {'U', "#.##.##.##.####"}, {'V', "#.##.##.##.#.#."}, {'W', "#.##.########.#"},
    {'X', "#.##.#.#.#.##.#"}, {'Y', "#.##.#.#..#..#."}, {'Z', "###..#.#.#..###"},
    {'.', ".............#."}, {'-', "......###......"}, {'+', "....#.###.#...."},
    {'=', "...###...###..."}, {':', "....#.....#...."}, {'/', "..#..#.#.#..#.."},
    {'(', "..#.#..#..#...#"}, {')', "#...#..#..#.#.."}, {',', "..........#.#.."},
    {'%', "#.#..#.#.#..#.#"}, {'<', "..#.#.#...#...#"}, {'>', "#...#...#.#.#.."},
};

static const char *rows_of(char c)
{
    c = (char)toupper((unsigned char)c);
    for (size_t i = 0; i < sizeof GLYPHS / sizeof GLYPHS[0]; i++)
        if (GLYPHS[i].c == c) return GLYPHS[i].rows;
    return NULL;
}

int pixel_font_width(const char *text, int scale)
{
    int n = (int)strlen(text);
    return n > 0 ? (4 * n - 1) * scale : 0;
}

int pixel_font_height(int scale) { return 5 * scale; }

void pixel_fill_rect(unsigned char *px, int width, int height, int channels, int x, int y, int w,
                     int h, unsigned colour)
{
    for (int j = y < 0 ? 0 : y; j < y + h && j < height; j++)
        for (int i = x < 0 ? 0 : x; i < x + w && i < width; i++) {
            unsigned char *p = px + ((size_t)j * width + i) * (size_t)channels;
            p[0] = (unsigned char)(colour >> 16);
            p[1] = (unsigned char)(colour >> 8);
            p[2] = (unsigned char)colour;
            if (channels == 4) p[3] = 255;
        }
}

void pixel_font_draw(unsigned char *px, int width, int height, int channels, int x, int y,
                     const char *text, int scale, unsigned colour)
{
    if (scale < 1) scale = 1;
    for (int k = 0; text[k]; k++) {
        const char *rows = rows_of(text[k]);
        if (!rows || strlen(rows) < 15) continue;
        for (int r = 0; r < 5; r++)
            for (int c = 0; c < 3; c++)
                if (rows[3 * r + c] == '#')
                    pixel_fill_rect(px, width, height, channels, x + (4 * k + c) * scale,
                                    y + r * scale, scale, scale, colour);
    }
}
