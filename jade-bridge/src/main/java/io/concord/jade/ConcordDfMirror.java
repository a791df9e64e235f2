package io.concord.jade;

import jade.core.AID;
import jade.core.Agent;
import jade.core.behaviours.TickerBehaviour;
import jade.domain.DFService;
import jade.domain.FIPAAgentManagement.DFAgentDescription;
import jade.domain.FIPAException;

import java.util.HashMap;
import java.util.HashSet;
import java.util.Map;
import java.util.Set;

/**
 * A JADE agent to drop into an existing JADE container: it keeps the DF entries of a Concord
 * platform mirrored into this JADE platform's own DF, with their HTTP addresses, so unchanged JADE
 * agents find Concord agents with their usual local {@code DFService.search} and talk to them.
 *
 * <pre>
 * java -cp jade.jar:concord-jade-bridge.jar:... jade.Boot -jade_mtp_http_parser io.concord.jade.JadeSaxParser \
 *      -agents "mirror:io.concord.jade.ConcordDfMirror(concord,http://10.0.0.5:7779/acc,1000)"
 * </pre>
 *
 * Arguments: the Concord platform's name, the URL of its ACC (the HTTP MTP of its container), and
 * optionally the refresh period in ms (1000). Entries that disappear from Concord's DF are removed
 * from JADE's.
 */
public class ConcordDfMirror extends Agent {
    private final Map<String, DFAgentDescription> mirrored = new HashMap<>();

    @Override
    protected void setup() {
        Object[] args = getArguments();
        if (args == null || args.length < 2) {
            throw new IllegalArgumentException("ConcordDfMirror needs (concord platform name, concord ACC url[, period ms])");
        }
        String platform = args[0].toString();
        String url = args[1].toString();
        long period = args.length > 2 ? Long.parseLong(args[2].toString()) : 1_000;
        AID concordDf = new AID("df@" + platform, AID.ISGUID);
        concordDf.addAddresses(url);
        addBehaviour(new TickerBehaviour(this, period) {
            @Override
            protected void onTick() {
                refresh(concordDf);
            }
        });
        refresh(concordDf);
    }

    private void refresh(AID concordDf) {
        DFAgentDescription[] found;
        try {
            found = DFService.search(this, concordDf, new DFAgentDescription());
        } catch (FIPAException e) {
            return; // the Concord platform is changing container or gone: try again next period
        }
        Set<String> now = new HashSet<>();
        for (DFAgentDescription d : found) {
            String name = d.getName().getName();
            now.add(name);
            DFAgentDescription old = mirrored.get(name);
            if (old != null && same(old, d)) {
                continue;
            }
            try {
                if (old != null) {
                    DFService.deregister(this, old);
                }
                DFService.register(this, d);
                mirrored.put(name, d);
            } catch (FIPAException e) {
                // JADE's DF refused this entry; the next period tries again
            }
        }
        for (String gone : new HashSet<>(mirrored.keySet())) {
            if (!now.contains(gone)) {
                try {
                    DFService.deregister(this, mirrored.remove(gone));
                } catch (FIPAException e) {
                    // already gone from JADE's DF
                }
            }
        }
    }

    private static boolean same(DFAgentDescription a, DFAgentDescription b) {
        return a.toString().equals(b.toString());
    }

    @Override
    protected void takeDown() {
        for (DFAgentDescription d : mirrored.values()) {
            try {
                DFService.deregister(this, d);
            } catch (FIPAException e) {
                // the DF is going too
            }
        }
    }
}
