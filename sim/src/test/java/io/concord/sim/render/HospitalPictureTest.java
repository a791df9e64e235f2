package io.concord.sim.render;

import io.concord.agents.chair.PoseController;
import io.concord.agents.map.HospitalMap;
import io.concord.agents.map.Point;
import io.concord.sim.world.ChairConfig;
import io.concord.sim.world.HospitalWorld;
import io.concord.sim.world.SimChair;

import org.junit.jupiter.api.Test;

import javax.imageio.ImageIO;
import java.awt.image.BufferedImage;
import java.nio.file.Path;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** Pictures into target/ for a person to look at: the map, and a run with paths and a collision. */
class HospitalPictureTest {

    @Test
    void theMapPictureShowsTheWholeHospital() throws Exception {
        Path png = Path.of("target", "pictures", "hospital-map.png");
        HospitalPicture.write(HospitalMap.defaultHospital(), png);
        BufferedImage img = ImageIO.read(png.toFile());
        assertTrue(img.getWidth() > 1000 && img.getHeight() > 400, img.getWidth() + "x" + img.getHeight());
    }

    @Test
    void aRunPictureShowsPathsOdometryDoorsObstaclesAndCollisions() throws Exception {
        HospitalWorld world = HospitalWorld.builder(HospitalMap.defaultHospital()).seed(5).build();
        SimChair a = world.addChair("chair1", ChairConfig.standard().withWheelErrors(0.004, 0.003), world.poseAt(19, 90));
        SimChair b = world.addChair("chair2", ChairConfig.standard(), world.poseAt(5, 180));
        world.door("WA").open();
        world.door("A3").open();
        world.door("WB").open();
        world.addBox("bed", new Point(15, 6.2), 2.0, 0.9, 0);
        world.addPerson("visitor", List.of(new Point(30.5, 11.6), new Point(46, 11.6)), 0.8, true);
        List<Point> routeA = List.of(new Point(24, 7.2), new Point(24, 10.8), new Point(22, 10.8), new Point(17.5, 10.8),
                new Point(12.5, 10.8), new Point(12.5, 15.6));
        PoseController control = PoseController.standard();
        int[] next = {0};
        world.addStepHook(() -> {
            if (a.latest() == null) {
                return;
            }
            if (next[0] < routeA.size() && control.reached(a.odometryPose(), routeA.get(next[0]).x(), routeA.get(next[0]).y())) {
                next[0]++;
            }
            var p = next[0] < routeA.size()
                    ? control.toPoint(a.odometryPose(), routeA.get(next[0]).x(), routeA.get(next[0]).y())
                    : PoseController.Powers.STOP;
            a.drive(p.left(), p.right());
        });
        b.drive(40, 40);   // west along the corridor and into the west wall
        world.run(40);
        Path png = Path.of("target", "pictures", "hospital-run.png");
        HospitalPicture.write(world, png);
        assertTrue(world.collisionCount() > 0, "chair2 met the wall");
        assertTrue(a.truthTrack().length() > 15, "chair1 drove its route: " + a.truthTrack().length());
        BufferedImage img = ImageIO.read(png.toFile());
        assertEquals(HospitalPicture.render(world).getWidth(), img.getWidth());
    }
}
