package jade.domain;

import io.concord.jadecompat.internal.AgentAccess;
import io.concord.jadecompat.internal.Engine;
import jade.core.AID;
import jade.core.Agent;
import jade.domain.FIPAAgentManagement.AMSAgentDescription;
import jade.domain.FIPAAgentManagement.SearchConstraints;

import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;

/**
 * JADE's helpers for the AMS. {@link #search} lists the platform's agents (those of Concord's
 * runtime here, and the AMS and the DF, as JADE lists them) with their states, filtered by the
 * description's name and state. Concord's AMS registers each agent itself: {@code register},
 * {@code deregister} and {@code modify} throw {@link UnsupportedOperationException}. To create
 * or kill agents through the AMS, send it a {@code jade.domain.JADEAgentManagement} action.
 */
public class AMSService extends FIPAService {
    public AMSService() {
    }

    public static AMSAgentDescription[] search(Agent a, AMSAgentDescription amsd) throws FIPAException {
        return search(a, a.getAMS(), amsd, null);
    }

    public static AMSAgentDescription[] search(Agent a, AMSAgentDescription amsd, SearchConstraints constraints) throws FIPAException {
        return search(a, a.getAMS(), amsd, constraints);
    }

    public static AMSAgentDescription[] search(Agent a, AID amsName, AMSAgentDescription amsd) throws FIPAException {
        return search(a, amsName, amsd, null);
    }

    /**
     * The descriptions of the platform's agents that match {@code amsd} (its name and state, where
     * set), at most {@code constraints}' max results (-1: all; unset: 1, as JADE's AMS).
     * {@code amsName} must be this platform's AMS.
     */
    public static AMSAgentDescription[] search(Agent a, AID amsName, AMSAgentDescription amsd, SearchConstraints constraints)
            throws FIPAException {
        Engine e = AgentAccess.get().engine(a);
        if (e == null) {
            throw new FIPAException("the agent " + a.getName() + " is not started");
        }
        if (amsName != null && !amsName.equals(a.getAMS())) {
            throw new FIPAException("only this platform's AMS is searched here, not " + amsName.getName());
        }
        Set<String> names = new LinkedHashSet<>();
        names.add("ams");
        names.add("df");
        names.addAll(e.liveAgentNames());
        long max = constraints == null || constraints.getMaxResults() == null ? 1 : constraints.getMaxResults();
        List<AMSAgentDescription> found = new ArrayList<>();
        for (String n : names) {
            if (max >= 0 && found.size() >= max) {
                break;
            }
            AMSAgentDescription d = new AMSAgentDescription();
            d.setName(new AID(n, AID.ISLOCALNAME));
            d.setState(stateOf(e.jadeAgent(n)));
            if (matches(amsd, d)) {
                found.add(d);
            }
        }
        return found.toArray(new AMSAgentDescription[0]);
    }

    private static boolean matches(AMSAgentDescription template, AMSAgentDescription d) {
        if (template == null) {
            return true;
        }
        if (template.getName() != null && !template.getName().equals(d.getName())) {
            return false;
        }
        return template.getState() == null || template.getState().equalsIgnoreCase(d.getState());
    }

    private static String stateOf(Agent a) {
        if (a == null) {
            return AMSAgentDescription.ACTIVE;
        }
        switch (a.getState()) {
            case Agent.AP_INITIATED:
                return AMSAgentDescription.INITIATED;
            case Agent.AP_SUSPENDED:
                return AMSAgentDescription.SUSPENDED;
            case Agent.AP_WAITING:
                return AMSAgentDescription.WAITING;
            default:
                return AMSAgentDescription.ACTIVE;
        }
    }

    public static void register(Agent a, AMSAgentDescription amsd) throws FIPAException {
        throw unsupported("register");
    }

    public static void register(Agent a, AID amsName, AMSAgentDescription amsd) throws FIPAException {
        throw unsupported("register");
    }

    public static void deregister(Agent a) throws FIPAException {
        throw unsupported("deregister");
    }

    public static void deregister(Agent a, AID amsName) throws FIPAException {
        throw unsupported("deregister");
    }

    public static void deregister(Agent a, AMSAgentDescription amsd) throws FIPAException {
        throw unsupported("deregister");
    }

    public static void deregister(Agent a, AID amsName, AMSAgentDescription amsd) throws FIPAException {
        throw unsupported("deregister");
    }

    public static void modify(Agent a, AMSAgentDescription amsd) throws FIPAException {
        throw unsupported("modify");
    }

    public static void modify(Agent a, AID amsName, AMSAgentDescription amsd) throws FIPAException {
        throw unsupported("modify");
    }

    private static UnsupportedOperationException unsupported(String what) {
        return new UnsupportedOperationException("AMSService." + what + " is not supported by concord-jade: Concord's AMS "
                + "registers and deregisters each agent itself");
    }
}
