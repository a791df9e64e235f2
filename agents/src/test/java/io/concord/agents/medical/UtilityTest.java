package io.concord.agents.medical;

import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The dissertation's utility (equation 6.1). */
class UtilityTest {

    @Test
    void theDissertationsCheckGives043() {
        assertEquals(0.43, MedicalAgent.utility(273.47, 134.86, 60, 3), 0.005);
    }

    @Test
    void priorityWeighsThePathAgainstTheQueue() {
        // A chair with a long queue but a short path, against one free but far away.
        double busyShort = MedicalAgent.utility(300, 60, 60, 3);
        double freeFar = MedicalAgent.utility(250, 200, 60, 3);
        assertTrue(busyShort > freeFar, "an emergency favours the short path");
        assertTrue(MedicalAgent.utility(250, 200, 60, 0) > MedicalAgent.utility(300, 60, 60, 0),
                "a routine task favours the chair done soonest");
    }
}
