package io.concord.sim.render;

import io.concord.agents.door.DoorDriver;
import io.concord.agents.chair.Pose;
import io.concord.agents.map.Area;
import io.concord.agents.map.Door;
import io.concord.agents.map.Edge;
import io.concord.agents.map.HospitalMap;
import io.concord.agents.map.Node;
import io.concord.agents.map.Point;
import io.concord.agents.map.Wall;
import io.concord.sim.world.Collision;
import io.concord.sim.world.HospitalWorld;
import io.concord.sim.world.Obstacle;
import io.concord.sim.world.SimChair;
import io.concord.sim.world.Track;
import io.concord.sim.world.WorldDoor;

import javax.imageio.ImageIO;
import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.Stroke;
import java.awt.geom.AffineTransform;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Line2D;
import java.awt.geom.Path2D;
import java.awt.geom.Rectangle2D;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.Locale;

/**
 * A picture of the hospital for a person to look at: areas, walls, doors in their state (red
 * closed, green open, orange moving, grey failed), the route graph with node ids, obstacles, and
 * every chair with its path travelled (solid: where it really went; dashed: where its odometry
 * thought it went) and its collisions (red crosses). Java2D, headless.
 */
public final class HospitalPicture {
    /** Chairs' colours: none of them a door's (red, green, orange, grey). */
    /** The chairs' colours, by chair number, none of the doors' red, orange or green; the console's map uses the same. */
    private static final int[] CHAIR_RGB = {0x1f77b4, 0x9467bd, 0xe6ab02, 0x17becf, 0xe377c2, 0x8c564b, 0x393b79, 0xbcbd22, 0x7b4173, 0x000000};
    private static final Color[] CHAIR_COLOURS = java.util.Arrays.stream(CHAIR_RGB).mapToObj(Color::new).toArray(Color[]::new);

    /** The colour of the chair at {@code index} (0 for chair1), as #rrggbb. */
    public static String chairColour(int index) {
        return String.format(Locale.ROOT, "#%06x", CHAIR_RGB[Math.floorMod(index, CHAIR_RGB.length)]);
    }
    private static final Color WALL = new Color(0x3a3a3a);
    private static final Color EDGE = new Color(0xb8c4d0);
    private static final Color NODE = new Color(0x2b4a6b);
    private static final Color CLOSED = new Color(0xc62828);
    private static final Color OPEN = new Color(0x2e7d32);
    private static final Color MOVING = new Color(0xef8f00);
    private static final Color FAILED = new Color(0x757575);

    private final double scale;
    private final int margin = 30;
    private final int legendHeight = 46;
    private final double minX;
    private final double maxY;
    private final int width;
    private final int height;

    private HospitalPicture(HospitalMap map, double pixelsPerMetre) {
        this.scale = pixelsPerMetre;
        double[] b = map.bounds();
        this.minX = b[0];
        this.maxY = b[3];
        this.width = (int) Math.ceil((b[2] - b[0]) * scale) + 2 * margin;
        this.height = (int) Math.ceil((b[3] - b[1]) * scale) + 2 * margin + legendHeight + 16;
    }

    /** Writes the map alone (doors closed), 24 pixels a metre. */
    public static void write(HospitalMap map, Path png) {
        HospitalPicture p = new HospitalPicture(map, 24);
        p.save(p.draw(map, null, map.name()), png);
    }

    /** Writes the world as it is now, with every chair's path, 24 pixels a metre. */
    public static void write(HospitalWorld world, Path png) {
        write(world, png, null);
    }

    /** Writes the world as it is now, with a caption (null: the map's name and the world time). */
    public static void write(HospitalWorld world, Path png, String caption) {
        HospitalPicture p = new HospitalPicture(world.map(), 24);
        p.save(p.draw(world.map(), world, title(world, caption)), png);
    }

    /**
     * Writes the world as it is now with the traffic agent's reservations ({@code TrafficAgent.holders()}:
     * node to the queue of chairs' agents, first the one whose turn it is): a ring round each node
     * in the colour of its first chair, and a smaller ring for each chair queued after it.
     */
    public static void write(HospitalWorld world, Path png, String caption, Map<Integer, List<String>> reservations) {
        write(world, png, caption, reservations, Map.of());
    }

    /**
     * The same, with the lanes' queues at nodes chairs pass in lanes ({@code TrafficAgent.lanes()}):
     * those rings are drawn at each lane's point, not at the node.
     */
    public static void write(HospitalWorld world, Path png, String caption, Map<Integer, List<String>> reservations,
                             Map<Integer, List<List<String>>> lanes) {
        HospitalPicture p = new HospitalPicture(world.map(), 24);
        BufferedImage img = p.draw(world.map(), world, title(world, caption));
        Graphics2D g = img.createGraphics();
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        p.reservations(g, world, reservations, lanes);
        g.dispose();
        p.save(img, png);
    }

    /** The caption, or the map's name and the world time. */
    private static String title(HospitalWorld world, String caption) {
        return caption != null ? caption : String.format(Locale.ROOT, "%s, t = %.1f s", world.map().name(), world.worldTimeNs() / 1e9);
    }

    /** The world drawn as an image. */
    public static BufferedImage render(HospitalWorld world) {
        HospitalPicture p = new HospitalPicture(world.map(), 24);
        return p.draw(world.map(), world, world.map().name());
    }

    private void save(BufferedImage img, Path png) {
        try {
            Path dir = png.toAbsolutePath().getParent();
            if (dir != null) {
                Files.createDirectories(dir);
            }
            ImageIO.write(img, "png", png.toFile());
        } catch (IOException e) {
            throw new UncheckedIOException("cannot write the picture " + png, e);
        }
    }

    private double px(double x) {
        return margin + (x - minX) * scale;
    }

    private double py(double y) {
        return margin + 16 + (maxY - y) * scale;
    }

    private BufferedImage draw(HospitalMap map, HospitalWorld world, String title) {
        BufferedImage img = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = img.createGraphics();
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
        g.setColor(Color.WHITE);
        g.fillRect(0, 0, width, height);
        g.setColor(Color.BLACK);
        g.setFont(new Font(Font.SANS_SERIF, Font.BOLD, 14));
        g.drawString(title, margin, 20);
        areas(g, map);
        edges(g, map);
        walls(g, map);
        doors(g, map, world);
        nodes(g, map);
        if (world != null) {
            obstacles(g, world);
            chairs(g, world);
        }
        legend(g, world);
        g.dispose();
        return img;
    }

    private void areas(Graphics2D g, HospitalMap map) {
        for (Area a : map.areas()) {
            Color fill = switch (a.kind()) {
                case WARD -> a.id().hashCode() % 2 == 0 ? new Color(0xe8f1fb) : new Color(0xeaf6ea);
                case ROOM -> null;
                case CORRIDOR -> new Color(0xf3f3f3);
                case HALL -> new Color(0xfdf6e3);
            };
            if (fill != null) {
                g.setColor(fill);
                g.fill(polygon(a.polygon()));
            }
        }
        g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 11));
        for (Area a : map.areas()) {
            if (a.kind() == Area.Kind.WARD) {
                continue;
            }
            double cx = 0;
            double top = -Double.MAX_VALUE;
            double bottom = Double.MAX_VALUE;
            double left = Double.MAX_VALUE;
            double right = -Double.MAX_VALUE;
            for (Point p : a.polygon()) {
                cx += p.x();
                top = Math.max(top, p.y());
                bottom = Math.min(bottom, p.y());
                left = Math.min(left, p.x());
                right = Math.max(right, p.x());
            }
            cx /= a.polygon().size();
            g.setColor(new Color(0x6b6b6b));
            String label = a.name();
            int w = g.getFontMetrics().stringWidth(label);
            // Rooms are labelled along the wall across from their door (their outer wall), corridors
            // along their middle line.
            int door = doorWall(map, left, right, bottom, top);
            double y = a.kind() == Area.Kind.ROOM ? (door < 0 || door == 0 && top > 12 ? top - 0.6 : bottom + 0.4)
                    : a.kind() == Area.Kind.CORRIDOR ? top - 0.5 : bottom + 0.5;
            g.drawString(label, (float) (px(cx) - w / 2.0), (float) py(y));
        }
        for (Area a : map.areas()) {
            if (a.kind() == Area.Kind.WARD) {
                double minx = Double.MAX_VALUE;
                double top = -Double.MAX_VALUE;
                for (Point p : a.polygon()) {
                    minx = Math.min(minx, p.x());
                    top = Math.max(top, p.y());
                }
                g.setColor(new Color(0x1a3d66));
                g.setFont(new Font(Font.SANS_SERIF, Font.BOLD, 13));
                g.drawString(a.name(), (float) px(minx), (float) py(top) - 3);
            }
        }
    }

    private void edges(Graphics2D g, HospitalMap map) {
        g.setStroke(new BasicStroke(1.5f));
        for (Edge e : map.edges()) {
            Point a = map.node(e.a()).at();
            Point b = map.node(e.b()).at();
            g.setColor(EDGE);
            if (e.twoLanes()) {
                // Two lanes: a thin line each, either side of the edge's own.
                double len = a.distanceTo(b);
                double ox = (b.y() - a.y()) / len * HospitalMap.LANE_OFFSET_M;
                double oy = -(b.x() - a.x()) / len * HospitalMap.LANE_OFFSET_M;
                Stroke was = g.getStroke();
                g.setStroke(new BasicStroke(1f));
                for (int side = -1; side <= 1; side += 2) {
                    g.draw(new Line2D.Double(px(a.x() + side * ox), py(a.y() + side * oy), px(b.x() + side * ox), py(b.y() + side * oy)));
                }
                g.setStroke(was);
            } else {
                g.draw(new Line2D.Double(px(a.x()), py(a.y()), px(b.x()), py(b.y())));
            }
        }
    }

    private void walls(Graphics2D g, HospitalMap map) {
        g.setColor(WALL);
        for (Wall w : map.walls()) {
            g.setStroke(new BasicStroke((float) Math.max(2, w.thicknessM() * scale), BasicStroke.CAP_SQUARE, BasicStroke.JOIN_MITER));
            g.draw(new Line2D.Double(px(w.from().x()), py(w.from().y()), px(w.to().x()), py(w.to().y())));
        }
    }

    private void doors(Graphics2D g, HospitalMap map, HospitalWorld world) {
        Stroke dashed = new BasicStroke(1f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10, new float[] {3, 3}, 0);
        g.setFont(new Font(Font.SANS_SERIF, Font.BOLD, 10));
        for (Door d : map.doors()) {
            WorldDoor wd = world == null || world.doors().isEmpty() ? null : world.door(d.id());
            Color c = wd == null ? CLOSED : wd.mechanismFailed() ? FAILED : wd.motion() != DoorDriver.Motion.STILL ? MOVING
                    : wd.isOpen() ? OPEN : wd.isClosed() ? CLOSED : MOVING;
            // Where the leaf moves, thin and dashed.
            g.setColor(new Color(c.getRed(), c.getGreen(), c.getBlue(), 120));
            g.setStroke(dashed);
            double w = d.width();
            switch (d.kind()) {
                case HINGED -> {
                    Point h = d.hingePoint();
                    Point f = d.freePoint();
                    double a0 = Math.toDegrees(Math.atan2(f.y() - h.y(), f.x() - h.x()));
                    boolean ccw = (d.hinge() == Door.End.FROM) == (d.swing() == Door.Side.LEFT);
                    g.draw(new java.awt.geom.Arc2D.Double(px(h.x()) - w * scale, py(h.y()) - w * scale, 2 * w * scale,
                            2 * w * scale, a0, ccw ? 90 : -90, java.awt.geom.Arc2D.OPEN));
                }
                case ROTATING -> g.draw(new Ellipse2D.Double(px(d.centre().x()) - w / 2 * scale,
                        py(d.centre().y()) - w / 2 * scale, w * scale, w * scale));
                case SLIDING -> { }
                default -> { }
            }
            double[] e;
            if (wd != null) {
                e = wd.leafEnds();
            } else {
                Point h = d.kind() == Door.Kind.HINGED ? d.hingePoint() : d.from();
                Point f = d.kind() == Door.Kind.HINGED ? d.freePoint() : d.to();
                e = new double[] {h.x(), h.y(), f.x(), f.y()};
            }
            g.setColor(c);
            g.setStroke(new BasicStroke(4f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER));
            g.draw(new Line2D.Double(px(e[0]), py(e[1]), px(e[2]), py(e[3])));
            if (d.kind() == Door.Kind.ROTATING) {
                g.fill(new Ellipse2D.Double(px(d.centre().x()) - 3, py(d.centre().y()) - 3, 6, 6));
            }
            g.setColor(c.darker());
            Point m = d.centre();
            boolean vertical = Math.abs(d.to().x() - d.from().x()) < Math.abs(d.to().y() - d.from().y());
            float lx = (float) (px(m.x()) + (vertical ? 5 : -6));
            // A door's name goes into the room it opens, above or below the wall.
            boolean above = inRoom(map, m.x(), m.y() + 0.3) || !inRoom(map, m.x(), m.y() - 0.3) && m.y() > 11;
            float ly = (float) (py(m.y()) + (vertical ? -w / 2 * scale - 4 : (above ? -6 : 15)));
            g.drawString(d.id(), lx, ly);
        }
    }

    /** -1 if a door of the map is in the bottom wall of this box, 1 if in its top wall, else 0. */
    private static int doorWall(HospitalMap map, double left, double right, double bottom, double top) {
        for (Door d : map.doors()) {
            Point m = d.centre();
            if (m.x() > left && m.x() < right && Math.abs(d.from().y() - d.to().y()) < 1e-6) {
                if (Math.abs(m.y() - bottom) < 0.05) {
                    return -1;
                }
                if (Math.abs(m.y() - top) < 0.05) {
                    return 1;
                }
            }
        }
        return 0;
    }

    private static boolean inRoom(HospitalMap map, double x, double y) {
        return map.areaAt(new Point(x, y)).map(a -> a.kind() == Area.Kind.ROOM).orElse(false);
    }

    private void nodes(Graphics2D g, HospitalMap map) {
        g.setFont(new Font(Font.SANS_SERIF, Font.BOLD, 10));
        for (Node n : map.nodes()) {
            double x = px(n.at().x());
            double y = py(n.at().y());
            g.setColor(Color.WHITE);
            g.fill(new Ellipse2D.Double(x - 8, y - 8, 16, 16));
            g.setColor(NODE);
            g.setStroke(new BasicStroke(1.5f));
            g.draw(new Ellipse2D.Double(x - 8, y - 8, 16, 16));
            String s = Integer.toString(n.id());
            int w = g.getFontMetrics().stringWidth(s);
            g.drawString(s, (float) (x - w / 2.0), (float) (y + 4));
        }
    }

    private void obstacles(Graphics2D g, HospitalWorld world) {
        for (Obstacle o : world.obstacles()) {
            Point p = o.position();
            double[] s = o.size();
            if (o.kind() == Obstacle.Kind.BOX) {
                AffineTransform t = new AffineTransform();
                t.translate(px(p.x()), py(p.y()));
                t.rotate(-o.angle());
                var shape = t.createTransformedShape(new Rectangle2D.Double(-s[0] / 2 * scale, -s[1] / 2 * scale,
                        s[0] * scale, s[1] * scale));
                g.setColor(new Color(0xa1887f));
                g.fill(shape);
                g.setColor(new Color(0x5d4037));
                g.draw(shape);
            } else {
                g.setColor(o.kind() == Obstacle.Kind.PERSON ? new Color(0x8e24aa) : new Color(0xa1887f));
                g.fill(new Ellipse2D.Double(px(p.x()) - s[0] / 2 * scale, py(p.y()) - s[0] / 2 * scale, s[0] * scale, s[0] * scale));
            }
            g.setColor(new Color(0x4a148c));
            g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 10));
            g.drawString(o.name(), (float) (px(p.x()) + s[0] / 2 * scale + 2), (float) py(p.y()));
        }
    }

    private void chairs(Graphics2D g, HospitalWorld world) {
        List<SimChair> chairs = world.chairs();
        for (int i = 0; i < chairs.size(); i++) {
            SimChair c = chairs.get(i);
            Color col = CHAIR_COLOURS[i % CHAIR_COLOURS.length];
            path(g, c.truthTrack(), col, new BasicStroke(2.2f, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
            path(g, c.odometryTrack(), col, new BasicStroke(1.4f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_ROUND, 10,
                    new float[] {6, 4}, 0));
            Pose p = c.truePose();
            AffineTransform t = new AffineTransform();
            t.translate(px(p.x()), py(p.y()));
            t.rotate(-p.heading());
            double l = c.layout().lengthM() * scale;
            double w = c.layout().widthM() * scale;
            var body = t.createTransformedShape(new Rectangle2D.Double(-l / 2, -w / 2, l, w));
            g.setColor(new Color(col.getRed(), col.getGreen(), col.getBlue(), 90));
            g.fill(body);
            g.setColor(col);
            g.setStroke(new BasicStroke(1.5f));
            g.draw(body);
            Path2D arrow = new Path2D.Double();
            arrow.moveTo(0, 0);
            arrow.lineTo(l / 2, 0);
            g.draw(t.createTransformedShape(arrow));
            g.setFont(new Font(Font.SANS_SERIF, Font.BOLD, 11));
            g.drawString(c.name(), (float) (px(p.x()) + 12), (float) (py(p.y()) - 12));
        }
        g.setColor(new Color(0xd50000));
        g.setStroke(new BasicStroke(2f));
        for (Collision x : world.collisions()) {
            double cx = px(x.at().x());
            double cy = py(x.at().y());
            g.draw(new Line2D.Double(cx - 5, cy - 5, cx + 5, cy + 5));
            g.draw(new Line2D.Double(cx - 5, cy + 5, cx + 5, cy - 5));
        }
    }

    private void reservations(Graphics2D g, HospitalWorld world, Map<Integer, List<String>> reservations,
                              Map<Integer, List<List<String>>> lanes) {
        List<SimChair> chairs = world.chairs();
        Map<String, Color> colours = new java.util.HashMap<>();
        for (int i = 0; i < chairs.size(); i++) {
            colours.put(chairs.get(i).name(), CHAIR_COLOURS[i % CHAIR_COLOURS.length]);
        }
        reservations.forEach((node, queue) -> {
            if (!world.map().hasNode(node)) {
                return;
            }
            List<List<String>> inLanes = lanes.get(node);
            if (inLanes != null && world.map().laned(node)) {
                for (int lane = 0; lane < 2; lane++) {
                    rings(g, colours, world.map().lanePoint(node, lane), inLanes.get(lane));
                }
            } else {
                rings(g, colours, world.map().node(node).at(), queue);
            }
        });
        int y = height - legendHeight + 28;
        int x = width - margin - 330;
        g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 11));
        g.setColor(CHAIR_COLOURS[0]);
        g.setStroke(new BasicStroke(3.5f));
        g.draw(new Ellipse2D.Double(x, y - 10, 12, 12));
        g.setColor(Color.DARK_GRAY);
        g.drawString("reserved: its turn", x + 16, y);
        x += 120;
        g.setColor(CHAIR_COLOURS[1]);
        g.setStroke(new BasicStroke(1.6f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_ROUND, 10, new float[] {3, 3}, 0));
        g.draw(new Ellipse2D.Double(x + 2, y - 8, 8, 8));
        g.setColor(Color.DARK_GRAY);
        g.drawString("queued after it (chair's colour)", x + 16, y);
    }

    /** A queue's rings at a point: a bold one in the colour of the chair whose turn it is, smaller dashed ones after it. */
    private void rings(Graphics2D g, Map<String, Color> colours, Point at, List<String> queue) {
        for (int k = 0; k < queue.size(); k++) {
            String agent = queue.get(k);
            String chair = agent.replaceFirst("@.*", "").replaceFirst("^control-", "");
            Color col = colours.getOrDefault(chair, Color.DARK_GRAY);
            double r = (k == 0 ? 0.75 : Math.max(0.25, 0.6 - 0.12 * k)) * scale;
            g.setColor(col);
            g.setStroke(k == 0 ? new BasicStroke(3.5f) : new BasicStroke(1.6f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_ROUND, 10,
                    new float[] {3, 3}, 0));
            g.draw(new Ellipse2D.Double(px(at.x()) - r, py(at.y()) - r, 2 * r, 2 * r));
        }
    }

    private void path(Graphics2D g, Track track, Color col, Stroke stroke) {
        if (track.size() < 2) {
            return;
        }
        Path2D p = new Path2D.Double();
        Point first = track.get(0);
        p.moveTo(px(first.x()), py(first.y()));
        for (int i = 1; i < track.size(); i++) {
            Point q = track.get(i);
            p.lineTo(px(q.x()), py(q.y()));
        }
        g.setColor(col);
        g.setStroke(stroke);
        g.draw(p);
    }

    private void legend(Graphics2D g, HospitalWorld world) {
        int y = height - legendHeight + 8;
        int x = margin;
        g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 11));
        x = swatch(g, x, y, CLOSED, "door closed");
        x = swatch(g, x, y, MOVING, "moving");
        x = swatch(g, x, y, OPEN, "open");
        x = swatch(g, x, y, FAILED, "failed");
        g.setColor(NODE);
        g.draw(new Ellipse2D.Double(x, y - 9, 12, 12));
        g.drawString("route node (id)", x + 16, y + 1);
        x += 120;
        g.setColor(CHAIR_COLOURS[0]);
        g.setStroke(new BasicStroke(2.2f));
        g.drawLine(x, y - 3, x + 24, y - 3);
        g.drawString("path travelled", x + 28, y + 1);
        x += 115;
        g.setStroke(new BasicStroke(1.4f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_ROUND, 10, new float[] {6, 4}, 0));
        g.drawLine(x, y - 3, x + 24, y - 3);
        g.drawString("raw odometry (before the markers correct it)", x + 28, y + 1);
        x += 290;
        g.setColor(new Color(0xd50000));
        g.setStroke(new BasicStroke(2f));
        g.drawLine(x, y - 8, x + 10, y + 2);
        g.drawLine(x, y + 2, x + 10, y - 8);
        g.drawString("collision", x + 16, y + 1);
        x += 75;
        // Two lanes: a thin line each side of the edge's own, as the edges are drawn.
        g.setColor(EDGE);
        g.setStroke(new BasicStroke(1f));
        g.drawLine(x, y - 6, x + 24, y - 6);
        g.drawLine(x, y, x + 24, y);
        g.setColor(Color.DARK_GRAY);
        g.drawString("two lanes", x + 28, y + 1);
        if (world != null) {
            g.setColor(Color.DARK_GRAY);
            g.drawString(String.format(Locale.ROOT, "%d chair%s, %d collisions, %d steps at %.0f Hz", world.chairs().size(),
                    world.chairs().size() == 1 ? "" : "s",
                    world.collisionCount(), world.stepCount(), world.stepHz()), margin, y + 20);
        }
    }

    private int swatch(Graphics2D g, int x, int y, Color c, String label) {
        g.setColor(c);
        g.setStroke(new BasicStroke(4f));
        g.drawLine(x, y - 3, x + 20, y - 3);
        g.setColor(Color.DARK_GRAY);
        g.drawString(label, x + 24, y + 1);
        return x + 34 + g.getFontMetrics().stringWidth(label);
    }

    private Path2D polygon(List<Point> pts) {
        Path2D p = new Path2D.Double();
        p.moveTo(px(pts.get(0).x()), py(pts.get(0).y()));
        for (int i = 1; i < pts.size(); i++) {
            p.lineTo(px(pts.get(i).x()), py(pts.get(i).y()));
        }
        p.closePath();
        return p;
    }
}
