import jade.core.AID;
import jade.core.Agent;
import jade.util.leap.ArrayList;
import jade.util.leap.HashMap;
import jade.util.leap.Iterator;
import jade.util.leap.LinkedList;
import jade.util.leap.List;
import jade.util.leap.Map;
import jade.util.leap.Properties;

/** JADE's own collections (jade.util.leap), as older JADE code uses them. */
public class Lists extends Agent {
    @Override
    protected void setup() {
        List l = new ArrayList();
        l.add("b");
        l.add("c");
        l.add(0, "a");
        System.out.println("list " + l.size() + " first " + l.get(0) + " index of c " + l.indexOf("c") + " contains z " + l.contains("z"));
        l.remove("b");
        StringBuilder b = new StringBuilder();
        for (Iterator it = l.iterator(); it.hasNext(); ) {
            b.append(it.next());
        }
        System.out.println("after remove " + b);
        LinkedList q = new LinkedList();
        q.addLast("x");
        q.addFirst("w");
        q.add("y");
        System.out.println("linked first " + q.removeFirst() + " size " + q.size());
        Map m = new HashMap();
        m.put("k", Integer.valueOf(1));
        m.put("j", Integer.valueOf(2));
        System.out.println("map " + m.get("k") + " " + m.containsKey("j") + " " + m.size() + " keys " + m.keySet().size());
        Properties p = new Properties();
        p.setProperty("a", "1");
        System.out.println("properties " + p.getProperty("a"));
        AID aid = new AID("x@corpus", AID.ISGUID);
        aid.addAddresses("http://127.0.0.1:7778/acc");
        aid.addAddresses("http://127.0.0.1:7779/acc");
        int n = 0;
        for (Iterator it = aid.getAllAddresses(); it.hasNext(); it.next()) {
            n++;
        }
        System.out.println("addresses " + n + " first " + aid.getAddressesArray()[0]);
        AID copy = (AID) aid.clone();
        System.out.println("clone equal " + copy.equals(aid) + " same hash " + (copy.hashCode() == aid.hashCode()));
        doDelete();
    }

    @Override
    protected void takeDown() {
        System.exit(0);
    }
}
