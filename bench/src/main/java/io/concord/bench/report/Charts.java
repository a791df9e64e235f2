package io.concord.bench.report;

import javax.imageio.ImageIO;
import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

/** Line charts as PNG, in the spirit of the dissertation's figures 7.13 to 7.16; java.awt only. */
public final class Charts {
    private static final Color[] COLORS = {new Color(0x1f77b4), new Color(0xd62728), new Color(0x2ca02c),
            new Color(0xff7f0e), new Color(0x9467bd)};

    private Charts() {
    }

    /**
     * @param series name to (x to y)
     */
    public static void line(Path file, String title, String xLabel, String yLabel, Map<String, TreeMap<Integer, Double>> series)
            throws IOException {
        line(file, title, xLabel, yLabel, series, false);
    }

    /**
     * @param pairs the series come in pairs to compare (a variant, then its baseline): one colour
     *              a pair, the second of each dashed, all of one width
     */
    public static void line(Path file, String title, String xLabel, String yLabel, Map<String, TreeMap<Integer, Double>> series,
                            boolean pairs) throws IOException {
        int w = 820;
        int h = 480;
        int left = 80;
        int right = 200;
        int top = 50;
        int bottom = 60;
        BufferedImage img = canvas(w, h);
        Graphics2D g = pen(img);
        double maxY = 0;
        int minX = Integer.MAX_VALUE;
        int maxX = Integer.MIN_VALUE;
        for (TreeMap<Integer, Double> s : series.values()) {
            for (Map.Entry<Integer, Double> e : s.entrySet()) {
                maxY = Math.max(maxY, e.getValue());
                minX = Math.min(minX, e.getKey());
                maxX = Math.max(maxX, e.getKey());
            }
        }
        if (maxY == 0 || minX == Integer.MAX_VALUE) {
            g.dispose();
            ImageIO.write(img, "png", file.toFile());
            return;
        }
        maxY *= 1.1;
        int pw = w - left - right;
        int ph = h - top - bottom;
        // Whole numbers, unless the scale is small (an idle cost in % of a core read 1, 1, 1, 0, 0, 0).
        String grid = maxY < 10 ? "%.2f" : "%.0f";
        axes(g, title, left, top, pw, ph, maxY, v -> String.format(java.util.Locale.ROOT, grid, v), 45);
        double spanX = Math.max(1, maxX - minX);
        java.util.TreeSet<Integer> xs = new java.util.TreeSet<>();
        series.values().forEach(s -> xs.addAll(s.keySet()));
        int labelledTo = Integer.MIN_VALUE;
        for (int x : xs) {
            int px = left + (int) (pw * (x - minX) / spanX);
            g.drawLine(px, top + ph, px, top + ph + 5);
            String label = Integer.toString(x);
            if (px - 5 > labelledTo + 4) { // a tick too close to the last label keeps its mark only (10 beside 100 on a scale to 5,000)
                g.drawString(label, px - 5, top + ph + 20);
                labelledTo = px - 5 + g.getFontMetrics().stringWidth(label);
            }
        }
        g.drawString(xLabel, left + pw / 2 - 30, h - 15);
        g.rotate(-Math.PI / 2);
        g.drawString(yLabel, -(top + ph / 2 + 40), 20);
        g.rotate(Math.PI / 2);
        int k = 0;
        for (Map.Entry<String, TreeMap<Integer, Double>> s : series.entrySet()) {
            Color c = COLORS[(pairs ? k / 2 : k) % COLORS.length];
            g.setColor(c);
            // Earlier series wider: where two lines coincide, the first still shows around the next.
            int wider = pairs ? 0 : series.size() - 1 - k;
            g.setStroke(pairs && k % 2 == 1 ? new BasicStroke(2.5f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_ROUND, 10, new float[] {8, 5}, 0)
                    : new BasicStroke(pairs ? 3f : 2.5f + 3f * wider));
            int r = pairs ? 4 : 4 + 2 * wider;
            int px0 = -1;
            int py0 = -1;
            for (Map.Entry<Integer, Double> e : s.getValue().entrySet()) {
                int px = left + (int) (pw * (e.getKey() - minX) / spanX);
                int py = top + ph - (int) (ph * e.getValue() / maxY);
                g.fillOval(px - r, py - r, 2 * r, 2 * r);
                if (px0 >= 0) {
                    g.drawLine(px0, py0, px, py);
                }
                px0 = px;
                py0 = py;
            }
            if (pairs) {
                g.drawLine(left + pw + 14, top + 17 + 22 * k, left + pw + 36, top + 17 + 22 * k);
                g.setColor(Color.BLACK);
                g.drawString(s.getKey(), left + pw + 40, top + 22 + 22 * k);
            } else {
                legend(g, k, s.getKey(), left + pw, top);
            }
            k++;
        }
        g.dispose();
        ImageIO.write(img, "png", file.toFile());
    }

    /**
     * Grouped bars: for each group (a label under the axis), one bar per series, in the series'
     * order and colours; each bar's value is written above it.
     */
    public static void bars(Path file, String title, String yLabel, List<String> groups, Map<String, List<Double>> series)
            throws IOException {
        int w = Math.max(820, 90 + 110 * groups.size() + 200);
        int h = 480;
        int left = 90;
        int right = 200;
        int top = 50;
        int bottom = 70;
        BufferedImage img = canvas(w, h);
        Graphics2D g = pen(img);
        double maxY = 0;
        for (List<Double> v : series.values()) {
            for (Double d : v) {
                if (d != null) {
                    maxY = Math.max(maxY, d);
                }
            }
        }
        maxY = maxY == 0 ? 1 : maxY * 1.15;
        int pw = w - left - right;
        int ph = h - top - bottom;
        axes(g, title, left, top, pw, ph, maxY, Charts::compact, 55);
        int groupW = pw / Math.max(1, groups.size());
        int n = series.size();
        int barW = Math.max(4, (groupW - 16) / Math.max(1, n));
        for (int gi = 0; gi < groups.size(); gi++) {
            int gx = left + gi * groupW + 8;
            int k = 0;
            for (Map.Entry<String, List<Double>> s : series.entrySet()) {
                Double v = gi < s.getValue().size() ? s.getValue().get(gi) : null;
                if (v != null) {
                    int bh = (int) (ph * v / maxY);
                    g.setColor(COLORS[k % COLORS.length]);
                    g.fillRect(gx + k * barW, top + ph - bh, barW - 2, bh);
                    g.setColor(Color.DARK_GRAY);
                    g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 9));
                    g.drawString(compact(v), gx + k * barW, top + ph - bh - 3);
                }
                k++;
            }
            g.setColor(Color.BLACK);
            g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 11));
            String label = groups.get(gi);
            int sp = label.indexOf(' ');
            g.drawString(sp < 0 ? label : label.substring(0, sp), gx, top + ph + 16);
            if (sp >= 0) {
                g.drawString(label.substring(sp + 1), gx, top + ph + 30);
            }
        }
        g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 12));
        g.rotate(-Math.PI / 2);
        g.drawString(yLabel, -(top + ph / 2 + 40), 20);
        g.rotate(Math.PI / 2);
        int k = 0;
        for (String name : series.keySet()) {
            g.setColor(COLORS[k % COLORS.length]);
            legend(g, k++, name, left + pw, top);
        }
        g.dispose();
        ImageIO.write(img, "png", file.toFile());
    }

    /** A white picture. */
    /** Draws on the image, anti-aliased. */
    private static Graphics2D pen(BufferedImage img) {
        Graphics2D g = img.createGraphics();
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        return g;
    }

    private static BufferedImage canvas(int w, int h) {
        BufferedImage img = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = img.createGraphics();
        g.setColor(Color.WHITE);
        g.fillRect(0, 0, w, h);
        g.dispose();
        return img;
    }

    /** The k-th line of the legend, right of the plot: a square in the current colour, and the name. */
    private static void legend(Graphics2D g, int k, String name, int plotRight, int top) {
        g.fillRect(plotRight + 20, top + 10 + 22 * k, 14, 14);
        g.setColor(Color.BLACK);
        g.drawString(name, plotRight + 40, top + 22 + 22 * k);
    }

    /** The title, the two axes, and five grid lines with their values, written by {@code label}. */
    private static void axes(Graphics2D g, String title, int left, int top, int pw, int ph, double maxY,
                             java.util.function.DoubleFunction<String> label, int labelWidth) {
        g.setColor(Color.BLACK);
        g.setFont(new Font(Font.SANS_SERIF, Font.BOLD, 16));
        g.drawString(title, left, 30);
        g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 12));
        g.drawLine(left, top + ph, left + pw, top + ph);
        g.drawLine(left, top, left, top + ph);
        for (int i = 0; i <= 5; i++) {
            double v = maxY * i / 5;
            int y = top + ph - (int) (ph * i / 5.0);
            g.setColor(new Color(0xdddddd));
            g.drawLine(left + 1, y, left + pw, y);
            g.setColor(Color.BLACK);
            g.drawString(label.apply(v), left - labelWidth, y + 4);
        }
    }

    /** 1234567 as 1.2M, 45600 as 45.6k. */
    static String compact(double v) {
        if (v >= 1e6) {
            return String.format(java.util.Locale.ROOT, "%.1fM", v / 1e6);
        }
        if (v >= 1e3) {
            return String.format(java.util.Locale.ROOT, "%.1fk", v / 1e3);
        }
        return String.format(java.util.Locale.ROOT, "%.2f", v);
    }

    public static Map<String, TreeMap<Integer, Double>> series(List<String> names) {
        Map<String, TreeMap<Integer, Double>> m = new LinkedHashMap<>();
        names.forEach(n -> m.put(n, new TreeMap<>()));
        return m;
    }
}
