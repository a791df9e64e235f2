package io.concord.jadecompat;

import io.concord.jadecompat.internal.Engine;
import org.junit.jupiter.api.Test;

import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The engine's start-up checks and the threads JADE agents get. */
class EngineTest {
    @Test
    void jadesOwnJarIsNotOnTheClassPathOfTheseTests() {
        // The build leaves JADE's jar out of this module's test class path (it runs only in the corpus's child JVMs);
        // with it there, the engine warns at start-up, and this check names the class it found.
        assertNull(Engine.jadeOnTheClassPath());
    }

    @Test
    void anAgentThreadIsVirtualFromJava21AndAPlatformThreadBefore() throws Exception {
        CountDownLatch ran = new CountDownLatch(1);
        Thread t = Engine.newAgentThread("probe", ran::countDown);
        t.start();
        assertTrue(ran.await(10, TimeUnit.SECONDS));
        boolean virtual = t.getClass().getName().equals("java.lang.VirtualThread");
        assertEquals("probe", t.getName());
        assertEquals(Runtime.version().feature() >= 21, virtual);
        assertEquals(Runtime.version().feature() >= 21, Engine.virtualThreads());
    }
}
