package io.concord.sim.board;

import io.concord.agents.medical.MedicalAgent;
import io.concord.console.Browser;
import io.concord.console.Console;
import io.concord.sim.HospitalView;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.openqa.selenium.By;
import org.openqa.selenium.WebElement;

import java.nio.file.Path;

import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * A serial chair (the board emulator on a pty pair) in the console, in a real headless Chromium:
 * drawn on the Hospital map where its own odometry has it, with its speed and its task; held
 * with a red ring and the reason after an e-stop; resumed from the page.
 */
class SerialChairConsoleTest {

    @Test
    void aSerialChairIsDrawnWithItsSpeedAndTaskHeldWithItsRingAndResumedInTheBrowser(@TempDir Path dir) throws Exception {
        try (ChairSafetyTest.Ward w = new ChairSafetyTest.Ward(dir, ChairSafetyTest.ALL, MedicalAgent.Settings.standard())) {
            HospitalView.FrontDesk desk = new HospitalView.FrontDesk();
            w.platform.startAgent("desk", desk);
            try (Console console = Console.start(w.platform, Console.Config.port(0));
                 Browser browser = new Browser()) {
                console.addView(new HospitalView(w.world, w.hospital, desk));
                browser.driver.get(console.uri());
                browser.until(d -> d.findElement(By.cssSelector("nav button[data-view='hospital']"))).click();
                // At the lobby's node 19, where it was started, armed.
                // (The map is drawn again with each snapshot: the element is read at once.)
                String[] at = browser.until(d -> {
                    WebElement c = d.findElement(By.cssSelector("circle#chair-chair1[data-serial='true'][data-safety='armed']"));
                    return new String[] {c.getAttribute("data-x"), c.getAttribute("data-y")};
                });
                String x0 = at[0];
                String y0 = at[1];
                w.transportUnderWay();
                // Under way (from node 19, where it stands, to node 3): it moves on the map, its speed and its task in the chairs' table, its bid in the tasks'.
                browser.until(d -> {
                    WebElement b = d.findElement(By.id("chair-chair1"));
                    return !b.getAttribute("data-x").equals(x0) || !b.getAttribute("data-y").equals(y0);
                });
                browser.until(d -> d.findElement(By.id("chairs")).getText().lines().anyMatch(l -> l.startsWith("chair1 (serial)")
                        && l.contains("T1 to_dropoff") && l.matches(".* [0-9]+\\.[0-9]{2} m/s .*") && !l.contains(" 0.00 m/s")));
                browser.until(d -> d.findElement(By.id("bids")).getText().lines().anyMatch(l -> l.startsWith("chair1 T1 19 → 3")));
                // The e-stop pressed and released: held, a red ring round it, the reason in its title and the table.
                w.board.command("estop on");
                w.awaitSaid("control-chair1: pauses T1: the e-stop was pressed", 10_000);
                w.board.command("estop off");
                browser.until(d -> d.findElements(By.cssSelector("circle#chair-chair1[data-safety='held'][stroke='#c0392b']")).size() == 1);
                held(browser);
                // Held, it stands: its wheels turn no more (the speed is the encoders' travel, not the located pose a marker moves);
                // its battery is the board's STATE frame's.
                browser.until(d -> d.findElement(By.id("chairs")).getText().lines().anyMatch(l -> l.startsWith("chair1 (serial)")
                        && l.matches(".* 0\\.00 m/s [0-9]+\\.[0-9] V .*")));
                browser.screenshot("hospital-serial-held");
                browser.until(d -> d.findElement(By.id("action-resume"))).click();
                browser.until(d -> d.findElement(By.id("view-said")).getText().matches("(chair1 resumes|asked chair1 to resume).*"));
                browser.until(d -> d.findElements(By.cssSelector("circle#chair-chair1[data-safety='armed'][stroke='#ffffff']")).size() == 1);
                w.drivesOnAfterTheResume();
                assertTrue(w.said("resume decided by"), w.tail());
            }
        }
    }

    /** Held, on the map and in the table, with the reason; what the page showed if not. */
    private static void held(Browser browser) {
        try {
            browser.until(d -> d.findElement(By.id("chair-chair1")).getAttribute("data-safety").equals("held")
                    && d.findElement(By.id("chairs")).getText().lines().anyMatch(l -> l.startsWith("chair1 (serial)")
                            && l.contains("held: the e-stop was pressed") && l.contains("needs Resume"))
                    && d.findElement(By.cssSelector("#chair-chair1 > title")).getAttribute("textContent").contains("the e-stop was pressed"));
        } catch (org.openqa.selenium.TimeoutException e) {
            throw new AssertionError("chairs: " + browser.driver.findElement(By.id("chairs")).getText() + "\ntitle: "
                    + browser.driver.findElement(By.cssSelector("#chair-chair1 > title")).getAttribute("textContent"), e);
        }
    }
}
