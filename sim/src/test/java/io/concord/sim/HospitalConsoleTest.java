package io.concord.sim;

import io.concord.agents.map.HospitalMap;
import io.concord.agents.medical.MedicalAgent;
import io.concord.console.Browser;
import io.concord.console.Console;
import io.concord.core.agent.PortRange;
import io.concord.layers.platform.Platform;
import io.concord.sim.world.ChairConfig;
import io.concord.sim.world.HospitalWorld;

import org.junit.jupiter.api.Test;
import org.openqa.selenium.By;
import org.openqa.selenium.WebElement;

import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;

import static org.junit.jupiter.api.Assertions.assertTrue;

/** The hospital view in a real headless Chromium: a transport asked for on the page moves a chair and opens a door. */
class HospitalConsoleTest {

    @Test
    void aTransportAskedForInTheBrowserMovesAChairAndOpensADoor() throws Exception {
        HospitalMap map = HospitalMap.defaultHospital();
        try (Platform platform = Platform.builder().name("hospital-ui").ports(new PortRange(7521, 80, 10)).build()) {
            HospitalWorld world = HospitalWorld.builder(map).seed(2010).build();
            world.addChair("chair1", ChairConfig.standard(), world.poseAt(19, 90));
            Hospital hospital = Hospital.start(platform, world, line -> { });
            world.attach(platform.runtime(), 20);
            platform.startAgent("medical", new MedicalAgent(line -> { }));
            HospitalView.FrontDesk desk = new HospitalView.FrontDesk();
            platform.startAgent("desk", desk);
            try (Console console = Console.start(platform, Console.Config.port(0));
                 Browser browser = new Browser()) {
                console.addView(new HospitalView(world, hospital, desk));
                // The ward is ready when every planner knows every door (asked on the loop).
                while (true) {
                    CompletableFuture<Boolean> ready = new CompletableFuture<>();
                    platform.runtime().execute(() -> ready.complete(hospital.ready()));
                    if (ready.get(10, TimeUnit.SECONDS)) {
                        break;
                    }
                    Thread.onSpinWait();
                }
                browser.driver.get(console.uri());
                WebElement tab = browser.until(d -> d.findElement(By.cssSelector("nav button[data-view='hospital']")));
                tab.click();
                WebElement chair = browser.until(d -> d.findElement(By.id("chair-chair1")));
                String startX = chair.getAttribute("data-x");
                String startY = chair.getAttribute("data-y");
                browser.screenshot("hospital-before");
                browser.until(d -> d.findElement(By.id("action-transport"))).click();
                browser.until(d -> d.findElement(By.id("view-said")).getText().startsWith("asked medical for a transport from node 3 to node 9"));
                browser.until(d -> {
                    WebElement c = d.findElement(By.id("chair-chair1"));
                    return !c.getAttribute("data-x").equals(startX) || !c.getAttribute("data-y").equals(startY);
                });
                browser.until(d -> d.findElements(By.cssSelector("polyline[id^='door-'][data-state='open']")).size() > 0);
                browser.until(d -> d.findElement(By.id("transports")).getText().contains("agreed"));
                browser.screenshot("hospital-console");
                assertTrue(browser.driver.findElement(By.id("bids")).getText().contains("chair1"));
            }
        }
    }
}
