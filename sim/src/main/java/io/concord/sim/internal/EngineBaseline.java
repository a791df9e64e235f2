package io.concord.sim.internal;

import io.concord.agents.map.HospitalMap;
import io.concord.agents.map.Node;
import io.concord.agents.map.Wall;

import org.jbox2d.collision.shapes.PolygonShape;
import org.jbox2d.common.Vec2;
import org.jbox2d.dynamics.Body;
import org.jbox2d.dynamics.BodyDef;
import org.jbox2d.dynamics.BodyType;
import org.jbox2d.dynamics.FixtureDef;
import org.jbox2d.dynamics.World;

import java.util.ArrayList;
import java.util.List;

/**
 * The physics engine alone, for the benchmark's floor: the map's walls as fixtures of one static
 * body and chair-sized boxes driven back and forth by setting their velocity, with no doors, no
 * sensors, no encoders, no reports, no clock. What the hospital world costs beyond this is its
 * own overhead. Not API.
 */
public final class EngineBaseline {
    private EngineBaseline() {
    }

    /**
     * Steps a second the bare engine makes with {@code chairs} boxes in the map's walls, measured
     * over {@code seconds} of wall time after as long again of warm-up.
     */
    public static double stepsPerSecond(HospitalMap map, int chairs, double seconds) {
        World world = new World(new Vec2(0, 0));
        world.setAllowSleep(true);
        Body ground = world.createBody(new BodyDef());
        for (Wall w : map.walls()) {
            PolygonShape s = new PolygonShape();
            float angle = (float) StrictMath.atan2(w.to().y() - w.from().y(), w.to().x() - w.from().x());
            s.setAsBox((float) (w.length() / 2), (float) (w.thicknessM() / 2),
                    new Vec2((float) ((w.from().x() + w.to().x()) / 2), (float) ((w.from().y() + w.to().y()) / 2)), angle);
            ground.createFixture(s, 0);
        }
        List<Node> nodes = map.nodes();
        List<Body> boxes = new ArrayList<>();
        for (int i = 0; i < chairs; i++) {
            Node n = nodes.get(i % nodes.size());
            BodyDef bd = new BodyDef();
            bd.type = BodyType.DYNAMIC;
            bd.position.set((float) n.at().x(), (float) n.at().y());
            Body b = world.createBody(bd);
            PolygonShape s = new PolygonShape();
            s.setAsBox(0.6f, 0.35f);
            FixtureDef fd = new FixtureDef();
            fd.shape = s;
            fd.density = 100f / (1.2f * 0.7f);
            b.createFixture(fd);
            boxes.add(b);
        }
        Vec2 v = new Vec2();
        long[] steps = {0};
        Runnable step = () -> {
            float dir = (steps[0] / 120) % 2 == 0 ? 0.8f : -0.8f;
            for (int i = 0; i < boxes.size(); i++) {
                v.set(dir, 0);
                boxes.get(i).setLinearVelocity(v);
                boxes.get(i).setAngularVelocity(0.1f * dir);
            }
            world.step(1 / 60f, 8, 3);
            steps[0]++;
        };
        // Wall time: this is a benchmark's measurement (bench's sim figures), not the platform's clock.
        long warmEnd = System.nanoTime() + (long) (seconds * 1e9);
        while (System.nanoTime() < warmEnd) {
            step.run();
        }
        long start = System.nanoTime();
        long first = steps[0];
        long end = start + (long) (seconds * 1e9);
        long now;
        do {
            for (int i = 0; i < 100; i++) {
                step.run();
            }
            now = System.nanoTime();
        } while (now < end);
        return (steps[0] - first) / ((now - start) / 1e9);
    }
}
