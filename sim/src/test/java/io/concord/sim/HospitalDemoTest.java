package io.concord.sim;

import io.concord.agents.map.HospitalMap;

import org.junit.jupiter.api.Test;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The hospital demo delivers the patient on the virtual clock, and refuses bad options. */
class HospitalDemoTest {

    @Test
    void theScenarioRunsEndToEndOnTheVirtualClock() throws Exception {
        Path png = Path.of("target", "pictures", "hospital-demo.png");
        Files.deleteIfExists(png);
        HospitalDemo.Options o = HospitalDemo.parse(new String[] {"--virtual", "--picture", png.toString()});
        assertTrue(HospitalDemo.run(HospitalMap.defaultHospital(), o), "the patient reached node 9");
        assertTrue(Files.size(png) > 10_000);
    }

    @Test
    void theRouteIsTheShortestByLength() {
        HospitalMap map = HospitalMap.defaultHospital();
        assertEquals(List.of(19, 22, 7, 6, 5, 4, 2, 3), HospitalDemo.leg(map, 19, 3));
        assertEquals(List.of(3, 2, 4, 5, 6, 7, 8, 10, 11, 12, 9), HospitalDemo.leg(map, 3, 9));
    }

    @Test
    void badOptionsSayWhatIsWrong() {
        assertTrue(assertThrows(IllegalArgumentException.class, () -> HospitalDemo.parse(new String[] {"--speed", "3"}))
                .getMessage().contains("unknown option '--speed'"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> HospitalDemo.parse(new String[] {"--speedup", "0"}))
                .getMessage().contains("(0, 1000]"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> HospitalDemo.parse(new String[] {"--seed"}))
                .getMessage().contains("needs a value"));
    }
}
