package io.concord.sim;

import io.concord.agents.chair.ChairDriver;
import io.concord.agents.chair.Pose;
import io.concord.core.agent.AgentRuntime;
import io.concord.testkit.FaultPlan;
import io.concord.testkit.Simulation;
import io.concord.agents.map.HospitalMap;
import io.concord.agents.map.Point;
import io.concord.sim.render.HospitalPicture;
import io.concord.sim.world.ChairConfig;
import io.concord.sim.world.HospitalWorld;
import io.concord.sim.world.SimChair;

import org.junit.jupiter.api.Test;

import java.nio.file.Path;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertTrue;

/** The README's hospital example, as written there, on the test kit's runtime. */
class ReadmeHospitalExampleTest {

    @Test
    void theReadmeExampleRuns() {
        try (Simulation sim = new Simulation(1, FaultPlan.NONE)) {
            AgentRuntime runtime = sim.newRuntime("host");
            // --- as in the README ---
            HospitalMap map = HospitalMap.defaultHospital();
            HospitalWorld world = HospitalWorld.builder(map).seed(42).build();
            SimChair chair = world.addChair("chair1", ChairConfig.standard(), world.poseAt(19, 90));
            world.door("WA").open();
            world.addPerson("visitor", List.of(new Point(30, 11), new Point(46, 11)), 0.9, true);
            world.addBox("bed", new Point(15, 6.2), 2.0, 0.9, 0);

            ChairDriver driver = chair;
            driver.setListener(r -> {
                Pose where = r.odometry();
                double ahead = r.range(driver.layout().sensorIndex("front"));
                driver.drive(ahead < 0.5 ? 0 : 50, ahead < 0.5 ? 0 : 50);
            });
            world.attach(runtime);
            // --- end ---
            sim.runFor(20_000);
            HospitalPicture.write(world, Path.of("target", "pictures", "readme-example.png"));
            // North from node 19 to the corridor's north wall, where the sonar stops it.
            assertTrue(chair.truePose().y() > 11 && chair.bumps() == 0, "stopped short of the wall: " + chair.truePose());
        }
    }
}
